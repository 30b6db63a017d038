// Property tests of the quadrature stimulus, for both edge placements (the signals' half
// count and the rig's whole count): over seeded random sequences of moves (both directions,
// pauses, trapezoids, ramps, reversals inside a segment, fractional start positions and
// distances) the edges take the count from count_at(start) to count_at(end) one count at a
// time, each edge sits where the profile crosses its count boundary (to the solver's
// documented rounding: the nearest ns), and a decoder fed the edges reads the same count.
// Plus the two stimulus faults of issue 16 as named cases.

#include "signals/move_builders.hpp"
#include "signals/quadrature_decoder.hpp"
#include "signals/quadrature_edges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

namespace {

QuadratureEncoder counts_encoder(EdgePlacement placement, std::uint32_t lines = 100) {
  QuadratureEncoder enc;
  enc.lines_per_turn = lines;
  enc.units_per_turn = 4.0 * lines; // the profile is in counts
  enc.placement = placement;
  return enc;
}

std::int64_t final_count(const MotionProfile& p, const QuadratureEncoder& enc) {
  return for_each_quadrature_edge(p, enc, [](const QuadEdge&) {});
}

std::size_t edge_count(const MotionProfile& p, const QuadratureEncoder& enc) {
  std::size_t n = 0;
  for_each_quadrature_edge(p, enc, [&](const QuadEdge&) { ++n; });
  return n;
}

// The profile's position at a time between nanoseconds (the oracle for edge times): the
// closed form of the segment holding t, the end position held after the end.
double position_at(const MotionProfile& p, double t_ns) {
  if (t_ns < static_cast<double>(p.start_time().count())) return p.position(p.start_time());
  if (t_ns >= static_cast<double>(p.end_time().count())) return p.end_position();
  const Segment& s = p.segments()[p.segment_index(Nanos{static_cast<std::int64_t>(std::floor(t_ns))})];
  const double dt = (t_ns - static_cast<double>(s.start.count())) * 1e-9;
  return s.position + (s.velocity + 0.5 * s.acceleration * dt) * dt;
}

// A seeded random move sequence. Moves that need rest (trapezoid, pause) follow a ramp to 0.
MotionProfile random_profile(std::mt19937_64& rng) {
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  MotionProfile p(uniform(-500.0, 500.0), Nanos{static_cast<std::int64_t>(rng() % 1'000'000)});
  const MoveLimits limits{uniform(50.0, 20'000.0), uniform(500.0, 200'000.0), uniform(500.0, 200'000.0)};
  const int moves = 3 + static_cast<int>(rng() % 8);
  for (int m = 0; m < moves; ++m) {
    const bool rest = p.at_rest();
    switch (rng() % 6) {
    case 0:   // a trapezoid of whole counts, either way (the moves of the issue)
    case 1: { // or of a fractional distance
      if (!rest) ramp_to(p, 0.0, limits.deceleration);
      const double whole = static_cast<double>(static_cast<std::int64_t>(rng() % 3000) - 1500);
      const double d = (rng() % 6 == 1) ? uniform(-1500.0, 1500.0) : whole;
      if (d != 0.0) trapezoid_move(p, d, limits);
      break;
    }
    case 2: // a pause
      if (!rest) ramp_to(p, 0.0, limits.deceleration);
      p.dwell(Nanos{static_cast<std::int64_t>(1 + rng() % 5'000'000)});
      break;
    case 3: // spin at a speed (the velocity steps)
      constant_speed(p, uniform(-limits.max_speed, limits.max_speed),
                     Nanos{static_cast<std::int64_t>(1 + rng() % 50'000'000)});
      break;
    case 4: // a ramp to a speed, through zero when the sign changes
      ramp_to(p, uniform(-limits.max_speed, limits.max_speed), limits.acceleration);
      break;
    case 5: // a reversal inside one segment
      if (rest)
        constant_speed(p, uniform(-limits.max_speed, limits.max_speed), 1_ms);
      else
        reversal(p, limits.acceleration);
      break;
    }
  }
  return p;
}

// How many count boundaries the profile passes, piece by piece: each segment splits at its
// turning point into monotonic pieces, and a monotonic piece passes |count change| of them.
std::int64_t boundaries_passed(const MotionProfile& p, const QuadratureEncoder& enc) {
  std::int64_t n = 0;
  for (const Segment& s : p.segments()) {
    const double dur = s.duration.seconds();
    const double from = s.position;
    const double to = s.end_position();
    const double turn = s.acceleration != 0.0 ? -s.velocity / s.acceleration : -1.0;
    if (turn > 0.0 && turn < dur) {
      const double vertex = s.position + 0.5 * s.velocity * turn;
      n += std::llabs(enc.count_at(vertex) - enc.count_at(from)) +
           std::llabs(enc.count_at(to) - enc.count_at(vertex));
    } else {
      n += std::llabs(enc.count_at(to) - enc.count_at(from));
    }
  }
  return n;
}

class QuadratureProperty : public ::testing::TestWithParam<EdgePlacement> {};

TEST_P(QuadratureProperty, EdgesEqualTheCountChangeAndSitWhereTheProfileCrossesItsCount) {
  std::mt19937_64 rng(16'003);
  for (int trial = 0; trial < 300; ++trial) {
    QuadratureEncoder enc = counts_encoder(GetParam(), static_cast<std::uint32_t>(50 + rng() % 2000));
    enc.reversed = (rng() % 4) == 0;
    const MotionProfile p = random_profile(rng);
    const double cpu = enc.counts_per_unit();
    const std::int64_t start = enc.count_at(p.position(p.start_time()));
    const std::int64_t end = enc.count_at(p.end_position());

    QuadratureDecoder decoder(CountMode::X4, channel_a(start), channel_b(start));
    decoder.set_count(start);
    bool a = channel_a(start);
    bool b = channel_b(start);
    std::int64_t count = start;
    std::int64_t edges = 0;
    std::int64_t net = 0;
    Nanos last = Nanos::min();
    const std::int64_t solved = for_each_quadrature_edge(p, enc, [&](const QuadEdge& e) {
      ++edges;
      ASSERT_GE(e.time, last) << "trial " << trial;
      last = e.time;
      ASSERT_EQ(std::llabs(e.count - count), 1) << "trial " << trial;
      const bool up = e.count > count;
      net += up ? 1 : -1;
      count = e.count;
      (e.channel == QuadChannel::A ? a : b) = e.level == Level::High;
      ASSERT_EQ(decoder.update(a, b), up ? 1 : -1) << "trial " << trial;
      // The boundary between count n and n+1 is n + edge_offset (in counts).
      const double boundary = (static_cast<double>(up ? e.count - 1 : e.count) + enc.edge_offset()) / cpu;
      const double before = position_at(p, static_cast<double>(e.time.count()) - 0.5);
      const double after = position_at(p, static_cast<double>(e.time.count()) + 0.5);
      const double slack = 1e-9 * (1.0 + std::abs(boundary));
      const bool rising = (cpu > 0) == up; // the profile position rises through the boundary
      if (rising) {
        ASSERT_LE(before, boundary + slack) << "trial " << trial << " edge at " << e.time.count();
        ASSERT_GE(after, boundary - slack) << "trial " << trial << " edge at " << e.time.count();
      } else {
        ASSERT_GE(before, boundary - slack) << "trial " << trial << " edge at " << e.time.count();
        ASSERT_LE(after, boundary + slack) << "trial " << trial << " edge at " << e.time.count();
      }
    });
    if (HasFatalFailure()) return;
    EXPECT_EQ(solved, end) << "trial " << trial;
    EXPECT_EQ(count, end) << "trial " << trial;
    EXPECT_EQ(net, end - start) << "trial " << trial;                 // the count change exactly
    EXPECT_EQ(edges, boundaries_passed(p, enc)) << "trial " << trial; // no edge too many, none lost
    EXPECT_EQ(decoder.count(), end) << "trial " << trial;             // the round trip
    EXPECT_EQ(decoder.illegal_transitions(), 0U) << "trial " << trial;
  }
}

INSTANTIATE_TEST_SUITE_P(BothPlacements, QuadratureProperty,
                         ::testing::Values(EdgePlacement::HalfCount, EdgePlacement::WholeCount));

// Issue 16 (3): a reverse move of 300 counts that ends exactly on a whole count gave 301
// edges (the rig entered count -1 on reaching 0 instead of on falling below it).
TEST(QuadratureStimulus, ReverseMoveEndingOnAWholeCountGivesOneEdgePerCount) {
  for (const EdgePlacement placement : {EdgePlacement::HalfCount, EdgePlacement::WholeCount}) {
    const QuadratureEncoder enc = counts_encoder(placement);
    MotionProfile constant(300.0);
    constant_speed(constant, -50.0, 6_s); // 50 counts/s for 6 s: exactly 300 counts
    EXPECT_EQ(edge_count(constant, enc), 300U);
    EXPECT_EQ(final_count(constant, enc), 0);
    // A trapezoid whose closed form ends at 699.99999999999989 (found by sweeping limits).
    MotionProfile trapezoid(1000.0);
    trapezoid_move(trapezoid, -300.0, MoveLimits{137.3, 1913.7, 1913.7});
    EXPECT_EQ(edge_count(trapezoid, enc), 300U);
    EXPECT_EQ(final_count(trapezoid, enc), 700);
  }
}

// Issue 16 (3): 2000 counts, a pause, 250 counts: the board read 2249 (the first move's
// closed form stopped a hair short of 2000, so its last edge was never emitted).
TEST(QuadratureStimulus, MoveAfterAPauseKeepsItsLastEdge) {
  for (const EdgePlacement placement : {EdgePlacement::HalfCount, EdgePlacement::WholeCount}) {
    const QuadratureEncoder enc = counts_encoder(placement);
    for (const MoveLimits limits : {MoveLimits{137.3, 1913.7, 1913.7}, MoveLimits{249.2, 4654.8, 4654.8}}) {
      MotionProfile p(0.0);
      trapezoid_move(p, 2000.0, limits);
      EXPECT_EQ(final_count(p, enc), 2000);
      p.dwell(100_ms);
      trapezoid_move(p, 250.0, limits);
      EXPECT_EQ(edge_count(p, enc), 2250U);
      EXPECT_EQ(final_count(p, enc), 2250);
    }
  }
}

// The rig's placement: the edge into count n (going up) is at the instant the profile
// reaches n; at 1000 counts/s from 0 that is n ms, to the ns.
TEST(QuadratureStimulus, WholeCountEdgesSitOnTheCounts) {
  MotionProfile p(0.0);
  constant_speed(p, 1000.0, 10_ms);
  constant_speed(p, -1000.0, 10_ms);
  std::vector<QuadEdge> edges;
  for_each_quadrature_edge(p, counts_encoder(EdgePlacement::WholeCount),
                           [&](const QuadEdge& e) { edges.push_back(e); });
  ASSERT_EQ(edges.size(), 20U); // 0 -> 10 -> 0: count 10 is reached at the turn, 0 at the end
  for (std::int64_t n = 1; n <= 10; ++n)
    EXPECT_EQ(edges[static_cast<std::size_t>(n - 1)].time, Nanos{n * 1'000'000});
  // Down: count 9 as soon as the profile falls below 10 (at the turn, 10 ms), ... count 0
  // once it falls below 1, at 19 ms; it ends on 0 with no edge into -1.
  for (std::int64_t n = 9; n >= 0; --n)
    EXPECT_EQ(edges[static_cast<std::size_t>(19 - n)].time, Nanos{(20 - n - 1) * 1'000'000}) << n;
}

} // namespace
