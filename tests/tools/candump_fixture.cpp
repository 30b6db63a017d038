// Runs a seeded virtual CAN bus with classic, extended, remote and FD frames and writes
// DIR/bus.log (write_candump) and DIR/expected.txt, one line per frame taken from the
// TraceRecorder: "<time_ns> <id hex> <ext> <rtr> <fd> <brs> <esi> <len> <data hex|->".
// candump_log2asc.py feeds bus.log to can-utils' log2asc and compares what it reads.
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "drivers/virtual/can_bus.hpp"

using namespace hilrig;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: candump_fixture DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  Scheduler s;
  TraceRecorder trace;
  virt::CanBus bus(s, "can0", virt::CanBitTiming{500'000, 2'000'000}, &trace);
  CanPort* nodes[] = {&bus.attach("rig"), &bus.attach("dut"), &bus.attach("node")};
  (void)bus.attach("monitor");
  std::mt19937 rng(1436509052);
  auto next = [&rng] { return static_cast<std::uint32_t>(rng()); };
  static constexpr std::uint8_t kFdLengths[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  for (int i = 0; i < 300; ++i) {
    CanFrame f;
    f.extended = next() % 3 == 0;
    f.id = next() & (f.extended ? 0x1FFF'FFFFU : 0x7FFU);
    f.fd = next() % 3 == 0;
    if (f.fd) {
      f.brs = next() % 2 == 0;
      f.esi = next() % 5 == 0;
      f.len = kFdLengths[next() % 16];
    } else {
      f.rtr = next() % 6 == 0;
      f.len = static_cast<std::uint8_t>(next() % 9);
    }
    for (std::size_t k = 0; k < f.len && !f.rtr; ++k) f.data[k] = static_cast<std::uint8_t>(next());
    CanPort* from = nodes[next() % 3];
    s.at(Nanos{static_cast<std::int64_t>(next() % 200'000'000)}, [from, f] { from->send(f); });
  }
  s.run_until_idle();
  std::ofstream log(dir + "/bus.log");
  // A wall-clock epoch, as a real capture has: log2asc takes seconds == 0 for a new log.
  write_candump(trace, log, CandumpOptions{false, Nanos{1'436'509'052'000'000'000}});
  std::ofstream expected(dir + "/expected.txt");
  for (const TraceCanFrame& c : trace.can_frames()) {
    const CanFrame& f = c.frame;
    expected << c.time.count() << ' ' << std::hex << f.id << std::dec << ' ' << f.extended << ' ' << f.rtr
             << ' ' << f.fd << ' ' << f.brs << ' ' << f.esi << ' ' << static_cast<unsigned>(f.len) << ' ';
    if (f.rtr || f.len == 0) expected << '-';
    for (std::size_t k = 0; k < f.len && !f.rtr; ++k) {
      char hex[3];
      std::snprintf(hex, sizeof hex, "%02X", f.data[k]);
      expected << hex;
    }
    expected << '\n';
  }
  return 0;
}
