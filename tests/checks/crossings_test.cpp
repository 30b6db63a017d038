#include <gtest/gtest.h>

#include "rig/checks/crossings.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;

// 1000 counts/s: position in counts = t in ms, exactly (ns / 1e6 is correctly rounded).
double ramp(Nanos t) { return static_cast<double>(t.count()) / 1e6; }

TEST(Crossings, RisingRampCrossesAtTheFirstNanosecondAtOrAboveTheSetpoint) {
  // 5 counts at 1 count/ms: exactly 5 ms; also off the scan grid: 7.25 counts at 7.25 ms.
  auto c = find_crossings(ramp, 5.0, 0_ms, 10_ms, 1_ms, Direction::Rising);
  ASSERT_EQ(c.size(), 1U);
  EXPECT_EQ(c[0], 5_ms);
  c = find_crossings(ramp, 7.25, 0_ms, 10_ms, 1_ms, Direction::Rising);
  ASSERT_EQ(c.size(), 1U);
  EXPECT_EQ(c[0], 7_ms + 250_us);
}

TEST(Crossings, TriangleGivesOneRisingAndOneFallingCrossingEachCycle) {
  // Up 1 count/ms for 10 ms, then down: setpoint 4 crossed rising at 4 ms, falling at 16 ms.
  const auto tri = [](Nanos t) {
    const double ms = static_cast<double>(t.count()) / 1e6;
    return ms <= 10.0 ? ms : 20.0 - ms;
  };
  const auto both = find_crossings(tri, 4.0, 0_ms, 20_ms, 300_us, Direction::Both);
  ASSERT_EQ(both.size(), 2U);
  EXPECT_EQ(both[0], 4_ms);
  EXPECT_EQ(both[1], 16_ms);
  EXPECT_EQ(find_crossings(tri, 4.0, 0_ms, 20_ms, 300_us, Direction::Falling).size(), 1U);
  EXPECT_TRUE(find_crossings(tri, 11.0, 0_ms, 20_ms, 300_us, Direction::Both).empty());
}

TEST(Crossings, WithAModulusEveryTurnCrossesTheSetpoint) {
  // A shaft that keeps turning, 1 count/ms, full scale 10 counts: setpoint 4 is crossed at
  // 4, 14 and 24 ms on the way to 30 counts; without the modulus only at 4 ms.
  const auto c = find_crossings(ramp, 4.0, 0_ms, 30_ms, 1_ms, Direction::Rising, 10.0);
  ASSERT_EQ(c.size(), 3U);
  EXPECT_EQ(c[0], 4_ms);
  EXPECT_EQ(c[1], 14_ms);
  EXPECT_EQ(c[2], 24_ms);
  EXPECT_EQ(find_crossings(ramp, 4.0, 0_ms, 30_ms, 1_ms, Direction::Rising).size(), 1U);
  // Backwards from 30 to 0 counts: falling through 24, 14 and 4 at 6, 16 and 26 ms.
  const auto down = [](Nanos t) { return 30.0 - ramp(t); };
  const auto f = find_crossings(down, 4.0, 0_ms, 30_ms, 1_ms, Direction::Falling, 10.0);
  ASSERT_EQ(f.size(), 3U);
  EXPECT_EQ(f[0], 6_ms);
  EXPECT_EQ(f[1], 16_ms);
  EXPECT_EQ(f[2], 26_ms);
}

} // namespace
} // namespace hilrig::checks
