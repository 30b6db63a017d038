// Motion profiles and move builders: closed-form position/velocity and the classic move
// shapes, with expected values worked out by hand from the kinematics.

#include "signals/motion_profile.hpp"
#include "signals/move_builders.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

TEST(MotionProfile, ClosedFormInsideASegment) {
  // p = 10 + 2·t + 1.5·t² (a = 3): at t = 2 s, p = 10 + 4 + 6 = 20, v = 2 + 6 = 8.
  MotionProfile p(10.0, 1_s);
  p.append(Segment{1_s, 5_s, 10.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(p.position(3_s), 20.0);
  EXPECT_DOUBLE_EQ(p.velocity(3_s), 8.0);
  EXPECT_DOUBLE_EQ(p.acceleration(3_s), 3.0);
  EXPECT_EQ(p.end_time(), 6_s);
}

TEST(MotionProfile, HoldsStartAndEndPositionsOutside) {
  MotionProfile p(5.0, 1_s);
  p.accelerate(2.0, 1_s).cruise(1_s); // ends at 5 + 1 + 2 = 8 units, velocity 2
  EXPECT_DOUBLE_EQ(p.position(0_s), 5.0);
  EXPECT_DOUBLE_EQ(p.velocity(0_s), 0.0);
  EXPECT_DOUBLE_EQ(p.position(10_s), 8.0);
  EXPECT_DOUBLE_EQ(p.velocity(10_s), 0.0);
  EXPECT_DOUBLE_EQ(p.end_velocity(), 2.0);
}

// restart() keeps the segments' storage but nothing else: the profile is a new one from the
// given start (no segment, the start held, peak speed 0, appends chained from the new start).
TEST(MotionProfile, RestartedIsANewProfile) {
  MotionProfile p(5.0, 1_s);
  p.accelerate(40.0, 1_s).cruise(1_s).accelerate(-40.0, 1_s); // peak 40 units/s
  p.restart(-3.0, 7_s);
  EXPECT_TRUE(p.segments().empty());
  EXPECT_EQ(p.start_time(), 7_s);
  EXPECT_EQ(p.end_time(), 7_s);
  EXPECT_EQ(p.position(9_s), -3.0);
  EXPECT_EQ(p.peak_speed(), 0.0);
  // The same appends give the same profile as a fresh one, segment for segment.
  MotionProfile fresh(-3.0, 7_s);
  for (MotionProfile* q : {&p, &fresh}) q->accelerate(2.0, 1_s).cruise(2_s);
  ASSERT_EQ(p.segments().size(), fresh.segments().size());
  for (std::size_t i = 0; i < p.segments().size(); ++i) {
    EXPECT_EQ(p.segments()[i].start, fresh.segments()[i].start);
    EXPECT_EQ(p.segments()[i].position, fresh.segments()[i].position);
    EXPECT_EQ(p.segments()[i].velocity, fresh.segments()[i].velocity);
  }
  EXPECT_EQ(p.peak_speed(), 2.0);
  EXPECT_EQ(p.end_position(), fresh.end_position());
}

TEST(MotionProfile, SegmentIndexFindsTheSegmentContainingT) {
  MotionProfile p;
  p.accelerate(1.0, 1_s).cruise(2_s).accelerate(-1.0, 1_s);
  EXPECT_EQ(p.segment_index(500_ms), 0U);
  EXPECT_EQ(p.segment_index(1_s), 1U); // a boundary belongs to the later segment
  EXPECT_EQ(p.segment_index(2999_ms), 1U);
  EXPECT_EQ(p.segment_index(3500_ms), 2U);
}

// The hinted reads are the binary search's, whatever the hint: every hint from the first
// segment to past the last, at each boundary, a nanosecond either side of it, a midpoint,
// before the start and after the end; and one hint carried forward, then back, through all.
TEST(MotionProfile, HintedReadsEqualTheSearchForAnyHint) {
  MotionProfile p(3.0, 2_ms);
  for (int k = 1; k <= 12; ++k)
    p.accelerate(k % 2 == 0 ? -0.5 * k : 1.0 * k, Nanos{1'000'000 + 7 * k}).cruise(Nanos{k});
  const std::size_t n = p.segments().size();
  std::vector<Nanos> times{0_ns, p.start_time() - Nanos{1}, p.end_time(), p.end_time() + 1_s};
  for (const Segment& s : p.segments())
    for (const Nanos t : {s.start - Nanos{1}, s.start, s.start + Nanos{1}, s.start + s.duration / 2})
      times.push_back(t);
  for (const Nanos t : times) {
    for (std::size_t hint = 0; hint <= n + 1; ++hint) {
      std::size_t h = hint;
      EXPECT_EQ(p.segment_index(t, h), p.segment_index(t)) << "t " << t.count() << " hint " << hint;
      EXPECT_EQ(h, p.segment_index(t));
      h = hint;
      EXPECT_EQ(p.position(t, h), p.position(t)) << "t " << t.count() << " hint " << hint;
      h = hint;
      EXPECT_EQ(p.velocity(t, h), p.velocity(t)) << "t " << t.count() << " hint " << hint;
    }
  }
  std::size_t carried = 0;
  std::sort(times.begin(), times.end());
  for (const Nanos t : times) EXPECT_EQ(p.position(t, carried), p.position(t)) << "forward, t " << t.count();
  for (auto t = times.rbegin(); t != times.rend(); ++t)
    EXPECT_EQ(p.velocity(*t, carried), p.velocity(*t)) << "back, t " << t->count();
}

// The start held until 1 s, a dwell to 3 s, a move 3..6 s (up 1 count/s², cruise, down to
// speed 0 exactly), two dwells to 8 s and the end held: held_until() gives each standstill's
// last instant, and the position is the same through it.
TEST(MotionProfile, HeldUntilTheEndOfEachStandstill) {
  MotionProfile p(5.0, 1_s);
  p.dwell(2_s).accelerate(1.0, 1_s).cruise(1_s).accelerate(-1.0, 1_s).dwell(1_s).dwell(1_s);
  std::size_t hint = 0;
  EXPECT_EQ(p.held_until(0_s, hint), 3_s - 1_ns);
  EXPECT_EQ(p.held_until(1_s, hint), 3_s - 1_ns);
  EXPECT_EQ(p.held_until(3_s - 1_ns, hint), 3_s - 1_ns);
  EXPECT_EQ(p.held_until(3_s, hint), 3_s); // the move begins
  EXPECT_EQ(p.held_until(4500_ms, hint), 4500_ms);
  EXPECT_EQ(p.held_until(6_s - 1_ns, hint), 6_s - 1_ns);
  EXPECT_EQ(p.held_until(6_s, hint), Nanos::max()); // 2 dwells, then the end held for good
  EXPECT_EQ(p.held_until(20_s, hint), Nanos::max());
  for (const Nanos t : {0_s, 1_s, 2_s, 6_s, 7_s + 1_ns}) {
    const Nanos held = p.held_until(t, hint);
    const Nanos last = held == Nanos::max() ? 100_s : held;
    for (const Nanos u : {t + 1_ns, t + (last - t) / 2, last})
      EXPECT_EQ(p.position(u), p.position(t)) << "t " << t.count() << " u " << u.count();
  }
  // A profile that ends moving holds its end position after its end; one that starts moving
  // holds nothing at its start; no segment at all holds for good.
  MotionProfile moving(0.0, 0_s);
  moving.accelerate(2.0, 1_s);
  EXPECT_EQ(moving.held_until(0_s, hint), 0_s);
  EXPECT_EQ(moving.held_until(1_s, hint), Nanos::max());
  EXPECT_EQ(MotionProfile(3.0, 1_s).held_until(0_s, hint), Nanos::max());
}

TEST(MotionProfile, RejectsDwellWhileMovingAndBrokenSegments) {
  MotionProfile p;
  p.accelerate(1.0, 1_s);
  EXPECT_THROW(p.dwell(1_s), std::logic_error);
  EXPECT_THROW(p.append(Segment{2_s, 1_s, p.end_position(), 0.0, 0.0}), std::invalid_argument); // gap in time
  EXPECT_THROW(p.append(Segment{1_s, 1_s, 99.0, 0.0, 0.0}), std::invalid_argument); // position jump
  EXPECT_THROW(p.accelerate(1.0, 0_s), std::invalid_argument);
}

TEST(MoveBuilders, TrapezoidDurationFromItsFormula) {
  // D = 20,000 counts, v = 100,000 counts/s, a = 1e6, b = 5e5 counts/s²:
  // ta = v/a = 0.1 s (5,000 counts), td = v/b = 0.2 s (10,000 counts),
  // tc = (20,000 - 15,000) / 100,000 = 0.05 s; total 0.35 s.
  MotionProfile p;
  const TrapezoidPlan plan = trapezoid_move(p, 20'000.0, MoveLimits{100'000.0, 1e6, 5e5});
  EXPECT_FALSE(plan.triangle);
  EXPECT_EQ(plan.accel_time, 100_ms);
  EXPECT_EQ(plan.cruise_time, 50_ms);
  EXPECT_EQ(plan.decel_time, 200_ms);
  EXPECT_EQ(p.end_time(), 350_ms);
  EXPECT_NEAR(p.position(100_ms), 5'000.0, 1e-6);
  EXPECT_NEAR(p.position(150_ms), 10'000.0, 1e-6);
  EXPECT_NEAR(p.velocity(120_ms), 100'000.0, 1e-6);
  EXPECT_DOUBLE_EQ(p.end_position(), 20'000.0);
  EXPECT_TRUE(p.at_rest());
}

TEST(MoveBuilders, ShortMoveIsATriangle) {
  // D = 2,000, a = b = 1e6: v² / a = D, so v = sqrt(2e9) = 44,721.36 counts/s and each
  // ramp lasts v/a = 44.72136 ms; total 2·sqrt(D/a) = 89.4427191 ms.
  MotionProfile p;
  const TrapezoidPlan plan = trapezoid_move(p, 2'000.0, MoveLimits{100'000.0, 1e6, 1e6});
  EXPECT_TRUE(plan.triangle);
  EXPECT_EQ(plan.cruise_time, 0_ns);
  EXPECT_NEAR(static_cast<double>(plan.duration().count()), 89'442'719.1, 1.0);
  EXPECT_NEAR(plan.peak_velocity, 44'721.36, 0.01);
  EXPECT_NEAR(p.position(plan.accel_time), 1'000.0, 1e-6);
  EXPECT_DOUBLE_EQ(p.end_position(), 2'000.0);
}

TEST(MoveBuilders, NegativeDistanceMovesBackwards) {
  MotionProfile p(100.0);
  trapezoid_move(p, -40.0, MoveLimits{10.0, 100.0, 100.0});
  EXPECT_DOUBLE_EQ(p.end_position(), 60.0);
  EXPECT_LT(p.velocity(p.end_time() / 2), 0.0);
}

TEST(MoveBuilders, SCurveKeepsItsPhaseDurationsAndEndsExactly) {
  // v = 1,000, a = 10,000, j = 1e6: Tj = a/j = 10 ms, Ta = v/a - Tj = 90 ms; the two
  // acceleration phases cover v·(v/a + Tj) = 110 units, so 500 units cruise
  // 390 / 1,000 = 390 ms. Total 4·10 + 2·90 + 390 = 610 ms.
  MotionProfile p;
  const SCurvePlan plan = s_curve_move(p, 500.0, SCurveLimits{1'000.0, 10'000.0, 1e6, 8});
  EXPECT_EQ(plan.jerk_time, 10_ms);
  EXPECT_EQ(plan.accel_time, 90_ms);
  EXPECT_EQ(plan.cruise_time, 390_ms);
  EXPECT_EQ(p.end_time(), 610_ms);
  EXPECT_NEAR(p.end_position(), 500.0, 1e-9);
  EXPECT_TRUE(p.at_rest());
  // 8 steps per ramp: 4 ramps x 8 + 2 constant-acceleration phases + cruise.
  EXPECT_EQ(p.segments().size(), 35U);
  // At the end of the first ramp v = j·Tj²/2 = 50 (the midpoint staircase keeps it exact
  // up to the final distance rescale, which is tiny).
  EXPECT_NEAR(p.velocity(10_ms), 50.0, 0.5);
  EXPECT_NEAR(p.velocity(300_ms), 1'000.0, 10.0);
  // The acceleration never jumps by more than a/N = 1,250 between steps.
  double previous = 0.0;
  for (const Segment& s : p.segments()) {
    EXPECT_LE(std::abs(s.acceleration - previous), 10'000.0 / 8.0 + 1.0);
    previous = s.acceleration;
  }
}

TEST(MoveBuilders, ShortSCurveNeverReachesFullAcceleration) {
  // 2·j·Tj³ = D with j = 1e6, D = 0.25: Tj = cbrt(0.125e-6) = 5 ms; four ramps = 20 ms.
  MotionProfile p;
  const SCurvePlan plan = s_curve_move(p, 0.25, SCurveLimits{1'000.0, 10'000.0, 1e6, 5});
  EXPECT_EQ(plan.jerk_time, 5_ms);
  EXPECT_EQ(plan.accel_time, 0_ns);
  EXPECT_EQ(plan.cruise_time, 0_ns);
  EXPECT_NEAR(p.end_position(), 0.25, 1e-12);
}

TEST(MoveBuilders, ReversalPassesThroughZeroInsideOneSegment) {
  // From +500 units/s at 1,000 units/s²: 1 s to -500; zero at 0.5 s; back where it began.
  MotionProfile p;
  constant_speed(p, 500.0, 1_s);
  reversal(p, 1'000.0);
  EXPECT_EQ(p.segments().size(), 2U);
  EXPECT_EQ(p.end_time(), 2_s);
  EXPECT_NEAR(p.velocity(1500_ms), 0.0, 1e-9);
  EXPECT_NEAR(p.end_velocity(), -500.0, 1e-9);
  EXPECT_NEAR(p.end_position(), 500.0, 1e-9);
  EXPECT_NEAR(p.position(1500_ms), 625.0, 1e-9); // 500 + 500·0.5 - 500·0.25
}

TEST(MoveBuilders, PressStrokeBrakesToStandstill) {
  // 100 units/s for 50 ms, brake at 1,000 units/s²: stops 100 ms later after
  // v²/2b = 5 units.
  MotionProfile p;
  const PressStroke stroke = press_stroke(p, 100.0, 50_ms, 1'000.0);
  EXPECT_EQ(stroke.brake_applied, 50_ms);
  EXPECT_EQ(stroke.standstill, 150_ms);
  EXPECT_DOUBLE_EQ(stroke.stop_distance, 5.0);
  EXPECT_NEAR(p.end_position(), 10.0, 1e-9);
  EXPECT_TRUE(p.at_rest());
  p.dwell(10_ms); // standing still: a dwell is allowed
  EXPECT_EQ(p.end_time(), 160_ms);
}

// chained() is the profile of append() one segment at a time, in the vector's own storage.
// The segments given carry positions off by up to 1e-10 (within append's continuity
// tolerance): the profile's are the closed-form ends of the segment before, as append() stores
// them (the first one the start position), each to the bit; the peak speed is the largest
// |velocity| at either end of a segment: here the second segment's end, 3 + 2 * 1.5 = 6.
TEST(MotionProfile, ChainedIsAppendOneByOne) {
  const std::vector<Segment> given = {
      Segment{1_s, 1_s, 10.0 + 1e-10, 3.0, 0.0},
      Segment{2_s, 1500_ms, 13.0 - 1e-10, 3.0, 2.0},
      Segment{3500_ms, 250_ms, 19.75 + 1e-10, -1.0, 0.5},
  };
  MotionProfile appended(10.0, 1_s);
  for (const Segment& s : given) appended.append(s);
  std::vector<Segment> storage = given;
  const Segment* block = storage.data();
  const MotionProfile chained = MotionProfile::chained(10.0, 1_s, std::move(storage));
  EXPECT_EQ(chained.segments().data(), block); // not copied
  ASSERT_EQ(chained.segments().size(), given.size());
  EXPECT_EQ(chained.segments()[0].position, 10.0);
  EXPECT_EQ(chained.segments()[1].position, 10.0 + 3.0 * 1.0);
  EXPECT_EQ(chained.segments()[2].position, 13.0 + (3.0 + 0.5 * 2.0 * 1.5) * 1.5);
  for (std::size_t i = 0; i < given.size(); ++i) {
    const Segment& a = chained.segments()[i];
    const Segment& b = appended.segments()[i];
    EXPECT_EQ(a.start, b.start);
    EXPECT_EQ(a.duration, b.duration);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.acceleration, b.acceleration);
    EXPECT_FALSE(a.settled_end.has_value());
  }
  EXPECT_EQ(chained.peak_speed(), 6.0);
  EXPECT_EQ(chained.peak_speed(), appended.peak_speed());
  EXPECT_EQ(chained.end_position(), appended.end_position());
  // What append() refuses, chained() refuses.
  EXPECT_THROW((void)MotionProfile::chained(10.0, 1_s, {Segment{1_s, 1_s, 10.1, 0.0, 0.0}}),
               std::invalid_argument);
  EXPECT_THROW((void)MotionProfile::chained(10.0, 1_s, {Segment{2_s, 1_s, 10.0, 0.0, 0.0}}),
               std::invalid_argument);
  EXPECT_THROW((void)MotionProfile::chained(10.0, 1_s, {Segment{1_s, 0_s, 10.0, 0.0, 0.0}}),
               std::invalid_argument);
}

// A move's seconds in closed form, before rounding, and the move built agrees with it.
// Trapezoid: 10 units at up to 2 units/s, a = b = 1: ramps 2 + 2 = 4 units in 4 s, the other 6
// at 2 units/s in 3 s: 7 s. Triangle: 1 unit at a = b = 1 peaks at 1 unit/s: 2 s. At rates
// near 0 the triangle is still long, not 0 s (a·b underflowed to 0 there).
TEST(MoveSeconds, TrapezoidTriangleAndTinyRates) {
  EXPECT_DOUBLE_EQ(trapezoid_seconds(10.0, {2.0, 1.0, 1.0}), 7.0);
  EXPECT_DOUBLE_EQ(trapezoid_seconds(-10.0, {2.0, 1.0, 1.0}), 7.0);
  EXPECT_DOUBLE_EQ(trapezoid_seconds(1.0, {2.0, 1.0, 1.0}), 2.0);
  EXPECT_DOUBLE_EQ(trapezoid_seconds(0.0, {2.0, 1.0, 1.0}), 0.0);
  EXPECT_NEAR(trapezoid_seconds(1.0, {600.0, 1e-300, 1e-300}) / 2e150, 1.0, 1e-12);
  EXPECT_EQ(plan_trapezoid(10.0, {2.0, 1.0, 1.0}).duration(), 7_s);
  // S-curve, jerk 1, a = 1, v = 10 units/s over 100 units: ramps tj = 1 s, ta = 9 s; the two
  // acceleration phases cover v·(v/a + tj) = 110 > 100, so no cruise: v²/a + v·tj = 100 gives
  // v = (-1 + sqrt(401)) / 2, ta = v - 1: 4 + 2·ta seconds.
  const double v = (-1.0 + std::sqrt(401.0)) / 2.0;
  EXPECT_NEAR(s_curve_seconds(100.0, {10.0, 1.0, 1.0}), 4.0 + 2.0 * (v - 1.0), 1e-12);
  MotionProfile p;
  EXPECT_NEAR(s_curve_move(p, 100.0, {10.0, 1.0, 1.0}).duration().seconds(), 4.0 + 2.0 * (v - 1.0), 1e-6);
}
