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

} // namespace
} // namespace hilrig::checks
