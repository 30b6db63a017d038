// Quadrature edges solved from a motion profile: exact times at constant speed, the right
// channel and level, reversals, and (property) decoding the edges gives the profile's count.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rig/campaign/quadrature_edges.hpp"
#include "signals/move_builders.hpp"

namespace hilrig::campaign {
namespace {

using namespace hilrig::literals;

TEST(QuadratureEdges, ForwardSequenceIsAThenB) {
  signals::MotionProfile p(0.0);
  signals::constant_speed(p, 1000.0, 10_ms);
  QuadratureEdges q(p);
  EXPECT_EQ(q.start_count(), 0);
  // Forward: 00 -> 10 (A rises) -> 11 (B rises) -> 01 (A falls) -> 00 (B falls).
  const bool on_a[] = {true, false, true, false, true};
  const Level level[] = {Level::High, Level::High, Level::Low, Level::Low, Level::High};
  for (int k = 1; k <= 5; ++k) {
    const auto e = q.next();
    ASSERT_TRUE(e.has_value());
    EXPECT_EQ(e->time, milliseconds(k)) << k;
    EXPECT_EQ(e->count, k);
    EXPECT_EQ(e->on_a, on_a[k - 1]) << k;
    EXPECT_EQ(e->level, level[k - 1]) << k;
  }
}

TEST(QuadratureEdges, StopsWhenTheProfileEnds) {
  signals::MotionProfile p(0.5);
  signals::constant_speed(p, 1000.0, 10_ms); // 0.5 -> 10.5: counts 1..10, the first at 0.5 ms
  QuadratureEdges q(p);
  int n = 0;
  Nanos first{-1};
  while (const auto e = q.next()) {
    if (n == 0) first = e->time;
    ++n;
  }
  EXPECT_EQ(n, 10);
  EXPECT_EQ(first, 500_us);
}

TEST(QuadratureEdges, AccelerationFromRestFollowsTheQuadratic) {
  // a = 2000 counts/s^2 from rest: position = 1000 t^2, count k at t = sqrt(k/1000) s.
  signals::MotionProfile p(0.0);
  p.accelerate(2000.0, 100_ms);
  QuadratureEdges q(p);
  for (int k = 1; k <= 10; ++k) {
    const auto e = q.next();
    ASSERT_TRUE(e.has_value());
    EXPECT_EQ(e->time, Nanos::from_seconds(std::sqrt(k / 1000.0))) << k;
  }
}

TEST(QuadratureEdges, ReversalInsideASegmentCountsBack) {
  // v0 = +100, a = -200: turns at t = 0.5 s at position 25, back to 0 at 1 s.
  signals::MotionProfile p(0.0);
  p.append(signals::Segment{0_ns, 1_s, 0.0, 100.0, -200.0});
  QuadratureEdges q(p);
  std::int64_t max_count = 0;
  std::int64_t last = 0;
  int n = 0;
  while (const auto e = q.next()) {
    max_count = std::max(max_count, e->count);
    last = e->count;
    ++n;
  }
  // Up 0 -> 25 (25 edges), down 25 -> -1 only if it falls below 0, which it reaches exactly
  // at the end: floor(0 - epsilon)... position returns to 0 at t = 1 s exactly, so the count
  // goes back to 0 (25 edges down), possibly one more at the exact end.
  EXPECT_EQ(max_count, 25);
  EXPECT_GE(last, -1);
  EXPECT_LE(last, 0);
  EXPECT_GE(n, 50);
  EXPECT_LE(n, 51);
}

// Decodes the A/B levels edge by edge (X4) and compares with the count the edge claims.
TEST(QuadratureEdges, PropertyDecodedCountMatchesProfile) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> speed(-5000.0, 5000.0);
  std::uniform_int_distribution<int> ms(1, 20);
  for (int trial = 0; trial < 50; ++trial) {
    signals::MotionProfile p(std::uniform_real_distribution<double>(-100.0, 100.0)(rng));
    for (int m = 0; m < 6; ++m) {
      if (m % 2 == 0)
        signals::constant_speed(p, speed(rng), milliseconds(ms(rng)));
      else
        p.accelerate(speed(rng) * 10.0, milliseconds(ms(rng)));
    }
    QuadratureEdges q(p);
    std::int64_t count = q.start_count();
    bool a = is_high(a_level(count));
    bool b = is_high(b_level(count));
    Nanos last = Nanos::min();
    while (const auto e = q.next()) {
      ASSERT_GE(e->time, last);
      last = e->time;
      // Exactly one channel changes, and the change is one count in the Gray order.
      if (e->on_a) {
        ASSERT_NE(a, is_high(e->level));
        a = is_high(e->level);
      } else {
        ASSERT_NE(b, is_high(e->level));
        b = is_high(e->level);
      }
      ASSERT_EQ(std::llabs(e->count - count), 1);
      const bool up = e->count > count;
      count = e->count;
      ASSERT_EQ(a, is_high(a_level(count)));
      ASSERT_EQ(b, is_high(b_level(count)));
      // The position at the edge is on the count boundary, to the ns rounding of its time:
      // count k is entered going up at position k, going down at position k + 1.
      const double boundary = static_cast<double>(up ? e->count : e->count + 1);
      ASSERT_NEAR(p.position(e->time), boundary, 1e-3);
    }
    EXPECT_EQ(count, static_cast<std::int64_t>(std::floor(p.end_position())))
        << "trial " << trial << " end position " << p.end_position();
  }
}

} // namespace
} // namespace hilrig::campaign
