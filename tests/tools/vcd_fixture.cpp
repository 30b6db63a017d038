// Writes a seeded random virtual-bus run as DIR/trace.vcd (write_vcd), DIR/stream.vcd
// (VcdStream, updated every 50 us of virtual time) and DIR/expected.txt: the declarations,
// initial values and samples taken from the TraceRecorder itself, for vcd_reader.py to
// compare with what it reads back from the VCD files.
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "core/vcd_stream.hpp"
#include "drivers/virtual/virtual_bus.hpp"

using namespace hilrig;
using namespace hilrig::literals;

namespace {

const char* kind_name(SignalKind k) {
  switch (k) {
  case SignalKind::Wire:
    return "wire";
  case SignalKind::Integer:
    return "integer";
  case SignalKind::Real:
    return "real";
  }
  return "?";
}

std::string value_text(const SignalInfo& s, std::int64_t v, double r) {
  if (s.kind == SignalKind::Real) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", r);
    return buf;
  }
  auto bits = static_cast<std::uint64_t>(v);
  if (s.width < 64) bits &= (std::uint64_t{1} << s.width) - 1U;
  return std::to_string(bits);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vcd_fixture DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  Scheduler s;
  TraceRecorder trace;
  virt::VirtualBus bus(s, &trace);
  std::mt19937 rng(20261122);
  auto next = [&rng] { return static_cast<std::uint32_t>(rng()); };
  auto& a = bus.line("rig.enc.A", Level::Low);
  auto& b = bus.line("rig.enc.B", Level::High);
  auto& z = bus.line("rig.enc.Z");
  auto& out1 = bus.line("dut.out1");
  out1.set_propagation_delay(330_ns);
  const std::uint32_t count = trace.declare("dut.count", SignalKind::Integer, 12);
  const std::uint32_t volt = trace.declare("dut.analog.volt", SignalKind::Real);
  trace.set_initial(count, 0);
  trace.set_initial_real(volt, 0.0);
  virt::DigitalLine* lines[] = {&a, &b, &z, &out1};
  for (int i = 0; i < 400; ++i) {
    const Nanos t{static_cast<std::int64_t>(next() % 1'000'000)};
    const unsigned what = next() % 6;
    const std::int64_t v = static_cast<std::int64_t>(next() % 5000) - 1000; // negatives too
    const double r = static_cast<double>(static_cast<int>(next() % 20000) - 10000) / 3.0;
    s.at(t, [&, what, v, r] {
      if (what < 4) {
        auto& line = *lines[what];
        line.driver().set(!line.driver().driven());
      } else if (what == 4) {
        trace.value(count, s.now(), v);
      } else {
        trace.real(volt, s.now(), r);
      }
    });
  }
  std::ofstream stream_file(dir + "/stream.vcd");
  VcdStream stream(stream_file);
  stream.update(trace);
  while (s.next_time() != Nanos::max()) {
    s.run_until(s.now() + 50_us);
    stream.update(trace);
  }
  std::ofstream vcd(dir + "/trace.vcd");
  write_vcd(trace, vcd);
  std::ofstream expected(dir + "/expected.txt");
  for (const SignalInfo& info : trace.signals()) {
    expected << "var " << info.name << ' ' << kind_name(info.kind) << ' ' << static_cast<unsigned>(info.width)
             << '\n';
  }
  for (const SignalInfo& info : trace.signals()) {
    expected << "at 0 " << info.name << ' '
             << (info.has_initial ? value_text(info, info.initial, info.initial_real) : "x") << '\n';
  }
  for (const TraceSample& sample : trace.samples()) {
    const SignalInfo& info = trace.signals()[sample.signal];
    expected << "at " << sample.time.count() << ' ' << info.name << ' '
             << value_text(info, sample.value, sample.real) << '\n';
  }
  return stream.skipped() == 0 && stream.late() == 0 ? 0 : 1;
}
