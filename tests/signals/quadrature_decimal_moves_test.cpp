// Moves as a user writes them (`hilrig synth quadrature`, positions in turns with few
// decimals, the rig's whole-count placement: count = floor(position)): a move ends on its
// target and takes the count there one edge per count, monotonically. Expected counts come
// from the decimals in integer arithmetic (thousandths of a turn times counts per turn), never
// from the solver. Plus the acceptance audit's cases, with edge counts derived by hand.

#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

namespace {

QuadratureEncoder rig_encoder(std::uint32_t lines) {
  QuadratureEncoder enc;
  enc.lines_per_turn = lines;
  enc.placement = EdgePlacement::WholeCount; // positions in turns, count = floor
  return enc;
}

// floor(milli_turns / 1000 · counts_per_turn), exactly.
std::int64_t count_of_milli_turns(std::int64_t milli_turns, std::uint32_t lines) {
  const std::int64_t scaled = milli_turns * 4 * static_cast<std::int64_t>(lines);
  const std::int64_t q = scaled / 1000;
  return (scaled % 1000 != 0 && scaled < 0) ? q - 1 : q;
}

struct Walk {
  std::int64_t initial = 0;
  std::vector<std::int64_t> counts; // after each A/B edge
};

Walk walk(const MotionProfile& p, const QuadratureEncoder& enc, Nanos until = Nanos::max()) {
  const QuadratureTrace trace = solve_quadrature(p, enc, until);
  Walk w{trace.initial_count, {}};
  for (const QuadEdge& e : trace.edges)
    if (e.channel != QuadChannel::Z) w.counts.push_back(e.count);
  return w;
}

// One edge per count from `from` to `to`, every edge one count further in the move's direction.
void expect_one_edge_per_count(const Walk& w, std::int64_t from, std::int64_t to, const std::string& what) {
  EXPECT_EQ(w.initial, from) << what;
  ASSERT_EQ(static_cast<std::int64_t>(w.counts.size()), std::abs(to - from)) << what;
  const std::int64_t dir = to > from ? 1 : -1;
  std::int64_t previous = from;
  for (std::size_t i = 0; i < w.counts.size(); ++i) {
    ASSERT_EQ(w.counts[i], previous + dir) << what << ", edge " << i;
    previous = w.counts[i];
  }
}

// The move itself never reverses: every segment's velocity keeps the move's sign (or is 0) at
// both ends, and no position is beyond the target.
void expect_monotonic_profile(const MotionProfile& p, double target, double dir, const std::string& what) {
  for (const Segment& s : p.segments()) {
    EXPECT_GE(dir * s.velocity, 0.0) << what;
    EXPECT_GE(dir * s.end_velocity(), 0.0) << what;
    EXPECT_LE(dir * s.position_at(s.end() - Nanos{1}), dir * target) << what;
  }
  EXPECT_EQ(p.end_position(), target) << what;
}

MotionProfile scurve(double start, double turns, double rpm, double accel, double jerk, int steps) {
  MotionProfile p(start);
  s_curve_move(p, turns, SCurveLimits{rpm / 60.0, accel, jerk, steps});
  return p;
}

MotionProfile trapezoid(double start, double turns, double rpm, double accel, double decel) {
  MotionProfile p(start);
  trapezoid_move(p, turns, MoveLimits{rpm / 60.0, accel, decel});
  return p;
}

} // namespace

// -0.5 turn at 400 counts/turn: 0 -> -200, 200 edges; the S-curve came back from -201.
TEST(DecimalMoves, SCurveHalfTurnBackwardsIsTwoHundredEdges) {
  const MotionProfile p = scurve(0.0, -0.5, 300, 100, 50000, 8);
  expect_one_edge_per_count(walk(p, rig_encoder(100)), 0, -200, "scurve -0.5");
}

// From 0.3 turn (count 120) by 2 turns (800 counts) to 920, 64 steps per ramp.
TEST(DecimalMoves, SCurveOfTwoTurnsFromAFractionIsEightHundredEdges) {
  const MotionProfile p = scurve(0.3, 2.0, 300, 100, 50000, 64);
  expect_one_edge_per_count(walk(p, rig_encoder(100)), 120, 920, "scurve 0.3 + 2");
}

// 0.3 turn is count 12 and 0.2 turn count 8 at 40 counts/turn: 4 edges (0.3 - 0.1 is
// 0.19999999999999998 in a double).
TEST(DecimalMoves, TrapezoidFromPointThreeByMinusPointOneIsFourEdges) {
  const MotionProfile p = trapezoid(0.3, -0.1, 600, 100, 100);
  expect_one_edge_per_count(walk(p, rig_encoder(10)), 12, 8, "trapezoid 0.3 - 0.1");
}

// -1.37 turn is count -548 and 1.13 turn count 452 at 400 counts/turn: 1000 edges, both shapes.
TEST(DecimalMoves, MoveFromMinusOnePointThreeSevenByTwoPointFiveIsOneThousandEdges) {
  expect_one_edge_per_count(walk(trapezoid(-1.37, 2.5, 600, 100, 100), rig_encoder(100)), -548, 452,
                            "trapezoid");
  expect_one_edge_per_count(walk(scurve(-1.37, 2.5, 600, 100, 50000, 8), rig_encoder(100)), -548, 452,
                            "scurve");
}

// -600 RPM is -10 turn/s: 10 ms from 0.3 turn (count 3000 at 10000 counts/turn) ends on 0.2
// turn, count 2000: 1000 edges.
TEST(DecimalMoves, ConstantSpeedFromPointThreeForTenMillisecondsIsOneThousandEdges) {
  MotionProfile p(0.3);
  constant_speed(p, -600.0 / 60.0, 10_ms);
  expect_one_edge_per_count(walk(p, rig_encoder(2500)), 3000, 2000, "constant -600 RPM");
}

// Seeded random moves as a user writes them: start and distance in thousandths (or
// hundredths, or tenths) of a turn, either sign, 1..2500 lines, S-curves and trapezoids.
TEST(DecimalMoves, RandomMovesTakeTheCountFromStartToTargetOneEdgeAtATime) {
  std::mt19937_64 rng(20261201);
  const auto pick = [&rng](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  const auto uniform = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  int extra_edge_moves = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::int64_t unit = std::vector<std::int64_t>{1, 10, 100}[static_cast<std::size_t>(pick(0, 2))];
    const std::int64_t start_milli = unit * pick(-3000 / unit, 3000 / unit);
    std::int64_t turns_milli = unit * pick(-3000 / unit, 3000 / unit);
    if (turns_milli == 0) turns_milli = unit;
    const auto lines = static_cast<std::uint32_t>(pick(0, 3) == 0 ? pick(1, 10) : pick(1, 2500));
    const double start = static_cast<double>(start_milli) / 1000.0;
    const double turns = static_cast<double>(turns_milli) / 1000.0;
    const double rpm = uniform(30.0, 3000.0);
    const double accel = uniform(5.0, 2000.0);
    const bool s_curve = pick(0, 1) == 0;
    const int steps = static_cast<int>(pick(1, 64));
    const MotionProfile p = s_curve ? scurve(start, turns, rpm, accel, uniform(100.0, 1e6), steps)
                                    : trapezoid(start, turns, rpm, accel, uniform(5.0, 2000.0));
    const std::string what = std::string(s_curve ? "scurve" : "trapezoid") + " trial " +
                             std::to_string(trial) + ": start " + std::to_string(start_milli) +
                             "/1000 turns " + std::to_string(turns_milli) + "/1000 lines " +
                             std::to_string(lines);
    const std::int64_t from = count_of_milli_turns(start_milli, lines);
    const std::int64_t to = count_of_milli_turns(start_milli + turns_milli, lines);
    const Walk w = walk(p, rig_encoder(lines));
    if (static_cast<std::int64_t>(w.counts.size()) != std::abs(to - from)) ++extra_edge_moves;
    expect_one_edge_per_count(w, from, to, what);
    expect_monotonic_profile(p, start + turns, turns > 0 ? 1.0 : -1.0, what);
  }
  EXPECT_EQ(extra_edge_moves, 0);
}
