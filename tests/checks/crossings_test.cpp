#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

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

// The setpoint is a class modulo the modulus: one given far from the position (any number of
// turns away, negative too) names the same crossings as its representative. 1e16 with a
// modulus of 10 once left the search stepping k where adding 1 changes nothing (without end).
TEST(Crossings, ASetpointTurnsAwayCrossesAsItsRepresentative) {
  const auto near = find_crossings(ramp, 4.0, 0_ms, 30_ms, 1_ms, Direction::Rising, 10.0);
  for (const double far : {14.0, -6.0, 4.0 + 10.0 * 1e9, 1e16 + 4.0, -1e16 + 4.0})
    EXPECT_EQ(find_crossings(ramp, far, 0_ms, 30_ms, 1_ms, Direction::Rising, 10.0), near) << far;
  // More than 2^53 moduli away (where k += 1 on the setpoint's own k moved nothing): a crossing
  // every count, 30 of them in 30 ms.
  const auto every_count = find_crossings(ramp, 0.0, 0_ms, 30_ms, 1_ms, Direction::Rising, 1.0);
  EXPECT_EQ(every_count.size(), 30U);
  EXPECT_EQ(find_crossings(ramp, 1e17, 0_ms, 30_ms, 1_ms, Direction::Rising, 1.0), every_count);
  // The fraction survives: 1e15 + 4.5 (a double holds eighths there) crosses half a count later.
  EXPECT_EQ(find_crossings(ramp, 1e15 + 4.5, 0_ms, 30_ms, 1_ms, Direction::Rising, 10.0).front(), 4'500_us);
}

// Up 1 count/ms to 2 counts at 2 ms, standing at exactly 2 until 7 ms, up to 4 at 9 ms,
// standing at 4 until 109 ms, then down 1 count/ms. held() tells where each standstill ends.
double stands(Nanos t) {
  const double ms = static_cast<double>(t.count()) / 1e6;
  if (t < 2_ms) return ms;
  if (t < 7_ms) return 2.0;
  if (t < 9_ms) return 2.0 + (ms - 7.0);
  if (t < 109_ms) return 4.0;
  return 4.0 - (ms - 109.0);
}
Nanos stands_held(Nanos t) {
  if (t >= 2_ms && t < 7_ms) return 7_ms - 1_ns;
  if (t >= 9_ms && t < 109_ms) return 109_ms - 1_ns;
  return t;
}

// Stepping over a standstill finds what sampling every step finds: levels at a standstill
// (2, 4), a hair either side of them (a crossing right where a standstill begins or ends),
// between them, and on a circle; every direction; steps that do and do not divide the
// standstills.
TEST(Crossings, HeldStandstillsGiveTheSameCrossingsAsEveryStep) {
  for (const double level : {2.0, 2.0 + 1e-9, 2.0 - 1e-9, 4.0, 4.0 + 1e-9, 4.0 - 1e-9, 3.0, 0.5}) {
    for (const Direction d : {Direction::Rising, Direction::Falling, Direction::Both}) {
      for (const Nanos step : {1_ms, 300_us, 7_us}) {
        for (const double modulus : {0.0, 1.5}) {
          const auto every = find_crossings(stands, level, 0_ms, 115_ms, step, d, modulus);
          const auto held = find_crossings(stands, level, 0_ms, 115_ms, step, d, modulus, stands_held);
          EXPECT_EQ(held, every) << "level " << level << " step " << step.count() << " modulus " << modulus;
        }
      }
    }
  }
  // The scan does find crossings here (the comparison above is not of empty lists).
  EXPECT_EQ(find_crossings(stands, 3.0, 0_ms, 115_ms, 7_us, Direction::Both, 0.0, stands_held),
            (std::vector<Nanos>{8_ms, 110_ms}));
}

// A standstill costs the scan a few reads, however long: 1,000 s at a 10 us step would be
// 10^8 samples.
TEST(Crossings, AHeldStandstillIsSteppedOverInOneGo) {
  std::size_t reads = 0;
  const auto still = [&](Nanos) {
    ++reads;
    return 7.0;
  };
  const auto forever = [](Nanos) { return Nanos::max(); };
  EXPECT_TRUE(find_crossings(still, 7.5, 0_ms, 1000_s, 10_us, Direction::Both, 0.0, forever).empty());
  EXPECT_LE(reads, 3U);
}

} // namespace
} // namespace hilrig::checks
