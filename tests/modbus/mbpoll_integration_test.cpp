// Integration: the virtual SMD23E served in real time on a free loopback port, driven by an
// independent Modbus client, Debian's mbpoll (mbpoll's references are 1-based: -r 1 is input
// register 0, -r 1025 is holding register 1024). Timing is never judged by the wall clock:
// the status is polled a bounded number of times until Move Complete, then checked exactly.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

constexpr const char* kMbpoll = "/usr/bin/mbpoll";

struct MbpollResult {
  int status = -1;
  std::string output;
};

MbpollResult mbpoll(std::uint16_t port, const std::string& args) {
  const std::string cmd =
      std::string(kMbpoll) + " -m tcp -a 1 -1 -o 2 -p " + std::to_string(port) + " " + args + " 2>&1";
  MbpollResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) {
    return r;
  }
  std::array<char, 512> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) {
    r.output += buf.data();
  }
  r.status = ::pclose(pipe);
  return r;
}

// The values of mbpoll's "[n]: \tvalue" lines, in order.
std::vector<long> values(const std::string& output) {
  std::vector<long> v;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] != '[') {
      continue;
    }
    const auto colon = line.find("]:");
    if (colon != std::string::npos) {
      v.push_back(std::stol(line.substr(colon + 2)));
    }
  }
  return v;
}

void write_outputs(std::uint16_t port, const std::string& words) {
  const MbpollResult r = mbpoll(port, "-r 1025 -t 4 127.0.0.1 " + words);
  ASSERT_EQ(r.status, 0) << r.output;
}

std::vector<long> read_inputs(std::uint16_t port, int count) {
  const MbpollResult r = mbpoll(port, "-r 1 -c " + std::to_string(count) + " -t 3 127.0.0.1");
  EXPECT_EQ(r.status, 0) << r.output;
  return values(r.output);
}

TEST(Smd23eOverModbusTcp, MbpollConfiguresTheUnitAndRunsARelativeMove) {
  ASSERT_EQ(::access(kMbpoll, X_OK), 0) << "this test needs Debian's mbpoll (apt install mbpoll)";
  ServeThread server{smd23e_on_tcp()}; // 127.0.0.1, free port, stopped and joined on every exit path
  const std::uint16_t port = server.port();

  // Power-up: unconfigured (M-05).
  ASSERT_EQ(read_inputs(port, 1), (std::vector<long>{0x6408}));

  // Configuration Mode: control 0x8000 (all inputs general purpose), driver enabled, inputs
  // NC, v_s = (1, 0) = 1000 steps/s, 2048 steps/turn, 1024 pulses, 50 % idle, 2.0 A.
  write_outputs(port, "32768 32768 1 0 2048 0 1024 50 20 0");
  EXPECT_EQ(read_inputs(port, 1), (std::vector<long>{0x8000})); // a copy of the control word

  // Command Mode, driver enabled; then Relative 2000 steps at 5000 steps/s, A = D = 100.
  write_outputs(port, "0 32768 0 0 0 0 0 0 0 0");
  write_outputs(port, "2 32768 2 0 5 0 100 100 0 0");
  // By §3.2: n_acc = (5000² − 1000²)/(2·100,000) = 120 steps each way, T = 0.432 s.

  std::vector<long> in;
  bool complete = false;
  for (int attempt = 0; attempt < 3000 && !complete; ++attempt) {
    in = read_inputs(port, 4);
    ASSERT_EQ(in.size(), 4U);
    complete = (in[0] & 0x0080) != 0;
  }
  ASSERT_TRUE(complete) << "no Move Complete after 3000 polls";
  // SW1: Controller OK, Position Invalid (never preset), Move Complete, Stopped.
  EXPECT_EQ(in[0], 0x4488);
  // SW2 without the heartbeat: driver enabled, the three NC inputs active.
  EXPECT_EQ(in[1] & ~0x0800L, 0x8007);
  // Motor Position (2, 0) = 2000 steps.
  EXPECT_EQ(in[2], 2);
  EXPECT_EQ(in[3], 0);

  // The output words read back through FC 3 at 1024.
  const MbpollResult back = mbpoll(port, "-r 1025 -c 4 -t 4 127.0.0.1");
  EXPECT_EQ(values(back.output), (std::vector<long>{2, 32768, 2, 0}));
}

TEST(Smd23eOverModbusTcp, ABadRequestFromMbpollIsAnExceptionAndTheServerCarriesOn) {
  ServeThread server{smd23e_on_tcp()};
  const MbpollResult bad = mbpoll(server.port(), "-r 101 -c 2 -t 3 127.0.0.1");
  EXPECT_NE(bad.output.find("Illegal data address"), std::string::npos) << bad.output;
  EXPECT_EQ(read_inputs(server.port(), 1), (std::vector<long>{0x6408}));
}

} // namespace
} // namespace hilrig::test
