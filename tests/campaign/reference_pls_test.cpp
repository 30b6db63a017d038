// The reference PLS on the virtual bus, driven by hand: its count, the window it switches
// on, its throughput (delay .. delay + scan), its variants and its host handshake.

#include <gtest/gtest.h>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "rig/duts/reference_pls.hpp"

namespace hilrig::duts {
namespace {

using namespace hilrig::literals;

struct Bench {
  Scheduler sched;
  TraceRecorder trace;
  virt::VirtualBus bus{sched, &trace};
  std::unique_ptr<Dut> dut;
  int count = 0; // the count the rig has played

  explicit Bench(const std::string& variant, std::int64_t on = 2, std::int64_t off = 5) {
    const DutInfo info = reference_pls_info();
    DutParams p = info.with_defaults({});
    p.set("on", on);
    p.set("off", off);
    dut = info.make(sched, p, variant, 0); // seed 0: scans at 200, 400, ... us
    dut->attach(bus, {{"A", "a"}, {"B", "b"}, {"OUT", "out"}});
  }
  // One forward count at time t: the X4 Gray sequence 00 -> 10 -> 11 -> 01.
  void forward_at(Nanos t) {
    sched.at(t, [this] {
      const int next = ++count;
      const int s = ((next % 4) + 4) % 4;
      bus.line("a").driver().set(level_of(s == 1 || s == 2));
      bus.line("b").driver().set(level_of(s == 2 || s == 3));
    });
  }
};

TEST(ReferencePls, OutputFollowsTheWindowAfterScanAndDelay) {
  Bench b("nominal");
  // Counts 1..6 at 1.05, 2.05, ... 6.05 ms. on = 2 at 2.05 ms -> scan at 2.2 ms -> pin at
  // 2.25 ms; off = 5 at 5.05 ms -> scan at 5.2 ms -> pin at 5.25 ms.
  for (int k = 1; k <= 6; ++k) b.forward_at(milliseconds(k) + 50_us);
  b.sched.run_until(10_ms);
  const std::vector<Edge> expected = {{2250_us, Level::High}, {5250_us, Level::Low}};
  EXPECT_EQ(b.trace.edges_of("out"), expected);
  EXPECT_EQ(static_cast<std::int16_t>(b.dut->host_read(1)), 6);
}

TEST(ReferencePls, LateVariantIsOneScanLater) {
  Bench b("late");
  for (int k = 1; k <= 6; ++k) b.forward_at(milliseconds(k) + 50_us);
  b.sched.run_until(10_ms);
  const std::vector<Edge> expected = {{2450_us, Level::High}, {5450_us, Level::Low}};
  EXPECT_EQ(b.trace.edges_of("out"), expected);
}

TEST(ReferencePls, OffByOneVariantSwitchesOneCountLate) {
  Bench b("off-by-one");
  for (int k = 1; k <= 7; ++k) b.forward_at(milliseconds(k) + 50_us);
  b.sched.run_until(10_ms);
  // Sees count - 1: on at count 3 (3.05 ms), off at count 6 (6.05 ms).
  const std::vector<Edge> expected = {{3250_us, Level::High}, {6250_us, Level::Low}};
  EXPECT_EQ(b.trace.edges_of("out"), expected);
}

TEST(ReferencePls, StuckOffNeverTurnsOn) {
  Bench b("stuck-off");
  for (int k = 1; k <= 6; ++k) b.forward_at(milliseconds(k) + 50_us);
  b.sched.run_until(10_ms);
  EXPECT_TRUE(b.trace.edges_of("out").empty());
}

TEST(ReferencePls, HandshakeProgramsSetpointsAndAcknowledges) {
  Bench b("nominal");
  b.sched.at(1_ms, [&] {
    b.dut->host_write(1, 10);
    b.dut->host_write(2, 20);
    b.dut->host_write(0, 0x0001);
    b.dut->host_write(0, 0x8001); // Transmit 0 -> 1
  });
  b.sched.run_until(1100_us);
  EXPECT_EQ(b.dut->host_read(0) & 0x8000U, 0U); // not yet: acts at its next scan
  b.sched.run_until(1300_us);
  EXPECT_EQ(b.dut->host_read(0) & 0x8000U, 0x8000U);
  EXPECT_EQ(b.dut->host_read(2), 10U);
  EXPECT_EQ(b.dut->host_read(3), 20U);
  b.sched.at(1400_us, [&] { b.dut->host_write(0, 0x0001); });
  b.sched.run_until(1700_us);
  EXPECT_EQ(b.dut->host_read(0) & 0x8000U, 0U); // Acknowledge follows Transmit down
}

TEST(ReferencePls, BadSetpointsAreRefusedWithTheErrorBit) {
  Bench b("nominal");
  b.sched.at(1_ms, [&] {
    b.dut->host_write(1, 20);
    b.dut->host_write(2, 10); // on >= off
    b.dut->host_write(0, 0x8001);
  });
  b.sched.run_until(2_ms);
  EXPECT_EQ(b.dut->host_read(0) & 0x0002U, 0x0002U);
  EXPECT_EQ(b.dut->host_read(2), 2U); // unchanged
}

} // namespace
} // namespace hilrig::duts
