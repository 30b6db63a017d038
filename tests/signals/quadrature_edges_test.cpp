// Quadrature edge solving: hand-computed edge times, channel order, index, reversals inside
// a segment, the streaming API, and a seeded property test that decoding the synthesized
// signals reproduces the profile's count at every edge and between edges.

#include "signals/move_builders.hpp"
#include "signals/quadrature_decoder.hpp"
#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_replay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

namespace {

QuadratureEncoder encoder_in_counts(std::uint32_t lines = 1024) {
  QuadratureEncoder enc;
  enc.lines_per_turn = lines;
  enc.units_per_turn = 4.0 * lines; // the profile is in counts
  return enc;
}

std::vector<QuadEdge> edges_of(const std::vector<QuadEdge>& all, QuadChannel ch) {
  std::vector<QuadEdge> out;
  for (const QuadEdge& e : all)
    if (e.channel == ch) out.push_back(e);
  return out;
}

} // namespace

TEST(QuadratureEdges, Lines1024At600RpmGive24_414usBetweenEdges) {
  // 600 RPM = 10 turns/s; 1,024 lines x 4 = 4,096 counts/turn -> 40,960 counts/s, so an
  // X4 edge every 1/40,960 s = 24,414.0625 ns, and each channel runs at 10.24 kHz.
  QuadratureEncoder enc; // 1,024 lines, profile in turns
  MotionProfile p;
  constant_speed(p, 10.0, 10_ms);
  const QuadratureTrace trace = solve_quadrature(p, enc);
  // 10 ms x 40,960 = 409.6 counts; edges sit at 0.5, 1.5, ... 409.5 counts: 410 edges.
  ASSERT_EQ(trace.edges.size(), 410U);
  EXPECT_EQ(trace.edges.front().time, 12'207_ns); // 0.5 / 40,960 s = 12,207.03 ns
  for (std::size_t i = 1; i < trace.edges.size(); ++i) {
    const std::int64_t gap = (trace.edges[i].time - trace.edges[i - 1].time).count();
    EXPECT_TRUE(gap == 24'414 || gap == 24'415) << "edge " << i << " gap " << gap;
    EXPECT_EQ(trace.edges[i].count, static_cast<std::int64_t>(i) + 1);
  }
  // Edge k (0-based) is at (k + 0.5) / 40,960 s: edge 100 at 2,453,613.28 ns.
  EXPECT_EQ(trace.edges[100].time, 2'453'613_ns);
  // Per channel: A rises every 4 counts = 97,656.25 ns (10.24 kHz).
  const auto a = edges_of(trace.edges, QuadChannel::A);
  EXPECT_EQ(a[0].level, Level::High);
  EXPECT_EQ(a[2].level, Level::High);
  EXPECT_NEAR(static_cast<double>((a[2].time - a[0].time).count()), 97'656.25, 1.0);
}

TEST(QuadratureEdges, ForwardMotionHasALeadingB) {
  MotionProfile p;
  constant_speed(p, 1'000.0, 5_ms); // counts/s: 5 counts
  const QuadratureTrace trace = solve_quadrature(p, encoder_in_counts());
  ASSERT_EQ(trace.edges.size(), 5U);
  // 00 -> 10 -> 11 -> 01 -> 00: A rises, B rises, A falls, B falls.
  EXPECT_EQ(trace.edges[0].channel, QuadChannel::A);
  EXPECT_EQ(trace.edges[0].level, Level::High);
  EXPECT_EQ(trace.edges[1].channel, QuadChannel::B);
  EXPECT_EQ(trace.edges[1].level, Level::High);
  EXPECT_EQ(trace.edges[2].channel, QuadChannel::A);
  EXPECT_EQ(trace.edges[2].level, Level::Low);
  EXPECT_EQ(trace.edges[3].channel, QuadChannel::B);
  EXPECT_EQ(trace.edges[3].level, Level::Low);
  EXPECT_EQ(trace.edges[0].time, 500'000_ns); // 0.5 count at 1,000 counts/s
}

TEST(QuadratureEdges, ReversedEncoderHasBLeading) {
  MotionProfile p;
  constant_speed(p, 1'000.0, 2_ms);
  QuadratureEncoder enc = encoder_in_counts();
  enc.reversed = true;
  const QuadratureTrace trace = solve_quadrature(p, enc);
  ASSERT_EQ(trace.edges.size(), 2U);
  EXPECT_EQ(trace.edges[0].channel, QuadChannel::B); // 00 -> 01
  EXPECT_EQ(trace.edges[0].level, Level::High);
  EXPECT_EQ(trace.edges[0].count, -1);
}

TEST(QuadratureEdges, AcceleratingEdgeTimesComeFromTheQuadratic) {
  // From rest at a = 2,000 counts/s²: c = 1,000·t², so count edge k + 0.5 is at
  // t = sqrt((k + 0.5) / 1,000): 22,360,679.77 ns for the first, 38,729,833.46 ns for the second.
  MotionProfile p;
  p.accelerate(2'000.0, 100_ms); // reaches 10 counts
  const QuadratureTrace trace = solve_quadrature(p, encoder_in_counts());
  ASSERT_EQ(trace.edges.size(), 10U);
  EXPECT_EQ(trace.edges[0].time, 22'360'680_ns);
  EXPECT_EQ(trace.edges[1].time, 38'729'833_ns);
  EXPECT_EQ(trace.edges[9].time, 97'467'943_ns); // sqrt(9.5e-3) s
}

TEST(QuadratureEdges, ReversalInsideASegmentSplitsAtTheTurningPoint) {
  // v0 = 1,000 counts/s, a = -2,000 counts/s² for 1 s: c = 1,000·t - 1,000·t², turning at
  // 0.5 s at 250 counts, back to 0 at 1 s. Up through 0.5 ... 249.5 (250 edges), down
  // through 249.5 ... 0.5 (250 edges). 249.5 is crossed at 0.5 s -/+ sqrt(0.5/1,000) s.
  MotionProfile p;
  p.append(Segment{0_ns, 1_s, 0.0, 1'000.0, -2'000.0});
  const QuadratureTrace trace = solve_quadrature(p, encoder_in_counts());
  ASSERT_EQ(trace.edges.size(), 500U);
  EXPECT_EQ(trace.edges[249].count, 250);
  EXPECT_EQ(trace.edges[249].time, 477'639'320_ns);
  EXPECT_EQ(trace.edges[250].count, 249);
  EXPECT_EQ(trace.edges[250].time, 522'360'680_ns);
  EXPECT_EQ(trace.edges.back().count, 0);
  for (std::size_t i = 1; i < trace.edges.size(); ++i)
    EXPECT_LE(trace.edges[i - 1].time, trace.edges[i].time);
  // Reversing puts the same channel's edge back: the last up edge and the first down edge
  // are the same line (B for state 249 <-> 250) in opposite directions.
  EXPECT_EQ(trace.edges[249].channel, trace.edges[250].channel);
  EXPECT_NE(trace.edges[249].level, trace.edges[250].level);
}

TEST(QuadratureEdges, IndexPulseByCountsAndGatedToAB) {
  // 2 lines = 8 counts per turn. Index at count 3, two counts wide: Z high in states 3, 4
  // (rising with the edge into state 3, falling with the edge into state 5), once per turn.
  QuadratureEncoder enc = encoder_in_counts(2);
  enc.index_count = 3;
  enc.index_width = 2;
  MotionProfile p;
  constant_speed(p, 1'000.0, 20_ms); // 20 counts = 2.5 turns: states 1 ... 20
  const auto z = edges_of(solve_quadrature(p, enc).edges, QuadChannel::Z);
  ASSERT_EQ(z.size(), 5U); // the turn-3 pulse is still high at 20 counts
  EXPECT_EQ(z[0].count, 3);
  EXPECT_EQ(z[0].level, Level::High);
  EXPECT_EQ(z[1].count, 5);
  EXPECT_EQ(z[1].level, Level::Low);
  EXPECT_EQ(z[2].count, 11);
  EXPECT_EQ(z[4].count, 19);

  // Gated to line 1: Z is high exactly in state 4·1 + 2 = 6, where A = B = 1.
  enc.gate_index_to_line(1);
  const auto gated = edges_of(solve_quadrature(p, enc).edges, QuadChannel::Z);
  ASSERT_EQ(gated.size(), 4U); // turns 1 and 2 (states 6 and 14)
  for (std::size_t i = 0; i < gated.size(); i += 2) {
    EXPECT_EQ(gated[i].level, Level::High);
    EXPECT_EQ(gated[i].count % 8, 6); // Z rises with the edge into 11 ...
    EXPECT_TRUE(channel_a(gated[i].count) && channel_b(gated[i].count));
    EXPECT_EQ(gated[i + 1].level, Level::Low);
    EXPECT_EQ(gated[i + 1].count % 8, 7);               // ... and falls with the edge out of it
    EXPECT_EQ(gated[i + 1].time - gated[i].time, 1_ms); // one count at 1,000 counts/s
  }
}

TEST(QuadratureEdges, StreamingInAnyBufferSizeGivesTheSameEdges) {
  MotionProfile p;
  trapezoid_move(p, 3'000.0, MoveLimits{50'000.0, 2e6, 1e6});
  reversal(p, 1e6);
  trapezoid_move(p, -1'234.0, MoveLimits{40'000.0, 1e6, 3e6});
  QuadratureEncoder enc = encoder_in_counts(256);
  enc.index_width = 3;
  const QuadratureTrace whole = solve_quadrature(p, enc);
  for (const std::size_t size : {2U, 3U, 7U, 64U}) {
    QuadratureEdgeSolver solver(p, enc);
    std::vector<QuadEdge> buffer(size);
    std::vector<QuadEdge> streamed;
    for (std::size_t n = solver.fill(buffer); n != 0; n = solver.fill(buffer))
      streamed.insert(streamed.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_EQ(streamed, whole.edges) << "buffer of " << size;
    EXPECT_TRUE(solver.done());
  }
  std::size_t calls = 0;
  const std::int64_t final_count = for_each_quadrature_edge(p, enc, [&](const QuadEdge&) { ++calls; });
  EXPECT_EQ(calls, whole.edges.size());
  EXPECT_EQ(final_count, enc.count_at(p.end_position()));
}

TEST(QuadratureEdges, OpenEndedProfileStopsAtUntil) {
  MotionProfile p;
  p.append(Segment{0_ns, Nanos::max(), 0.0, 1'000.0, 0.0});
  EXPECT_THROW(static_cast<void>(solve_quadrature(p, encoder_in_counts())), std::invalid_argument);
  const QuadratureTrace trace = solve_quadrature(p, encoder_in_counts(), 10_ms);
  EXPECT_EQ(trace.edges.size(), 10U); // 0.5 ... 9.5 counts
}

// Property: over seeded random profiles of accelerations, cruises, reversals and dwells
// (forward, backward and through zero speed inside segments), replaying the edges into an
// X4 decoder gives the profile's count after every edge and at every instant in between.
TEST(QuadratureEdges, DecodedCountFollowsRandomProfiles) {
  std::mt19937_64 rng(20261122);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  for (int trial = 0; trial < 40; ++trial) {
    QuadratureEncoder enc = encoder_in_counts(static_cast<std::uint32_t>(64 + rng() % 2000));
    enc.units_per_turn = uniform(0.5, 2.0); // profile in turns-ish units, arbitrary scale
    enc.reversed = (rng() & 1) != 0;
    MotionProfile p(uniform(-5.0, 5.0), Nanos{static_cast<std::int64_t>(rng() % 1000)});
    for (int s = 0; s < 12; ++s) {
      const Nanos d{static_cast<std::int64_t>(1 + rng() % 3'000'000)};
      switch (rng() % 4) {
      case 0:
        p.accelerate(uniform(-3'000.0, 3'000.0), d);
        break;
      case 1:
        p.cruise(d);
        break;
      case 2:
        constant_speed(p, uniform(-20.0, 20.0), d);
        break;
      case 3:
        p.append(
            Segment{p.end_time(), d, p.end_position(), uniform(-10.0, 10.0), uniform(-20'000.0, 20'000.0)});
        break;
      }
    }
    const QuadratureTrace trace = solve_quadrature(p, enc);
    ASSERT_EQ(trace.initial_count, enc.count_at(p.position(p.start_time())));
    QuadratureDecoder decoder(CountMode::X4, trace.initial_level(QuadChannel::A),
                              trace.initial_level(QuadChannel::B));
    decoder.set_count(trace.initial_count);
    Nanos previous = p.start_time();
    std::int64_t previous_count = trace.initial_count;
    std::size_t edge = 0;
    replay(trace, decoder, [&](Nanos t, const QuadratureDecoder& d) {
      while (edge < trace.edges.size() && trace.edges[edge].time == t) ++edge;
      EXPECT_EQ(d.count(), trace.edges[edge - 1].count) << "trial " << trial << " at " << t.count();
      // Between edges the profile must sit inside the state the decoder holds.
      if (t - previous >= 2_ns) {
        const Nanos mid = previous + (t - previous) / 2;
        EXPECT_EQ(enc.count_at(p.position(mid)), previous_count)
            << "trial " << trial << " at " << mid.count();
      }
      previous = t;
      previous_count = d.count();
    });
    EXPECT_EQ(decoder.illegal_transitions(), 0U);
    EXPECT_EQ(decoder.count(), enc.count_at(p.end_position())) << "trial " << trial;
  }
}

// Property: X2 and X1 decoding of the same signals. From state 0, X2 counts the A edges
// (state boundaries 0|1 and 2|3 mod 4) and X1 the 0|1 boundaries only, so after X4 count
// n they read ceil(n/2) and ceil(n/4), for negative n too (e.g. n = -2 crosses the 3|2
// boundary once: X2 = -1 = ceil(-1); n = -3 crosses no 0|1 boundary: X1 = 0 = ceil(-0.75)).
TEST(QuadratureEdges, X2AndX1DecodingFollowTheX4Count) {
  std::mt19937_64 rng(7);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  const auto ceil_div = [](std::int64_t n, std::int64_t d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); };
  for (int trial = 0; trial < 20; ++trial) {
    MotionProfile p; // starts at 0 counts: state 0
    for (int s = 0; s < 8; ++s)
      p.append(Segment{p.end_time(), Nanos{static_cast<std::int64_t>(1 + rng() % 2'000'000)},
                       p.end_position(), uniform(-50'000.0, 50'000.0), uniform(-5e7, 5e7)});
    const QuadratureTrace trace = solve_quadrature(p, encoder_in_counts(100));
    QuadratureDecoder x4(CountMode::X4), x2(CountMode::X2), x1(CountMode::X1);
    replay(trace, x2, [](Nanos, const QuadratureDecoder&) {});
    replay(trace, x1, [](Nanos, const QuadratureDecoder&) {});
    replay(trace, x4, [](Nanos, const QuadratureDecoder&) {});
    ASSERT_EQ(x4.count(), trace.edges.empty() ? 0 : trace.edges.back().count);
    EXPECT_EQ(x2.count(), ceil_div(x4.count(), 2)) << "trial " << trial;
    EXPECT_EQ(x1.count(), ceil_div(x4.count(), 4)) << "trial " << trial;
  }
}

// A move that ends on a count: the edge into that count is at the move's end time, not before
// it. Solved forward from the start of the deceleration, v0² + 2·a·d cancels near the end to
// a rounding residue whose square root put this edge microseconds early (11.1 us here).
// Closed form: 1 line = 4 counts/turn, 3,000 turns at up to 6,000 rpm (100 turns/s), accel 10
// and decel 0.01 turns/s². Reaching 100 turns/s and stopping again would take 100²/20 +
// 100²/0.02 = 500,500 turns, so the move is a triangle: v²·(1/(2·10) + 1/(2·0.01)) = 3,000,
// v = sqrt(6,000 / 100.1) = 7.742096611 turns/s; the ramps v/10 = 774,209,661 ns and
// v/0.01 = 774,209,661,139 ns, each rounded to the ns (plan_trapezoid), end at
// 774,983,870,800 ns. With the rig's WholeCount placement count n is entered when the
// position reaches n, so count 12,000 is entered at the end. Count 11,999 is entered 0.25 turn
// before the end: with the ramp's rounded rate b = v'/t_d, where v' = 3,000 / ((t_a + t_d)/2)
// = 7.742096611386664 turns/s and b = 0.0099999999999957 turns/s², sqrt(2·0.25/b) =
// 7.071067811867 s before it: 767,912,802,988 ns.
TEST(QuadratureEdges, AMoveEndingOnACountPutsItsLastEdgeAtItsEndTime) {
  QuadratureEncoder enc;
  enc.lines_per_turn = 1; // profile in turns
  enc.placement = EdgePlacement::WholeCount;
  MotionProfile p;
  trapezoid_move(p, 3000.0, MoveLimits{100.0, 10.0, 0.01});
  ASSERT_EQ(p.end_time(), 774'983'870'800_ns);
  const QuadratureTrace trace = solve_quadrature(p, enc);
  ASSERT_EQ(trace.edges.size(), 12'000U);
  EXPECT_EQ(trace.edges.back().count, 12'000);
  EXPECT_EQ(trace.edges.back().time, 774'983'870'800_ns);
  EXPECT_EQ(trace.edges[11'998].count, 11'999);
  EXPECT_EQ(trace.edges[11'998].time, 767'912'802'988_ns);
}

// Property: over seeded random trapezoids (rates from 1 to 1e7 counts/s², decelerations up to
// 1e6 times the accelerations either way) that end on a count boundary (WholeCount: an
// integer; HalfCount: an integer + 0.5), a move upwards enters its last count at its end time
// exactly, and the count before it at sqrt(2·(1 count)/b) before the end (D = b·τ²/2 on the
// last ramp, b its rate as planned), to the nanosecond's rounding. A move downwards enters its
// last count one count before its end (the edge down sits at the boundary the position falls
// below, and the move stops on its end boundary): at the same sqrt(2/b) before the end.
TEST(QuadratureEdges, TrapezoidsEndingOnACountEnterItAtTheirEndTime) {
  std::mt19937_64 rng(20261129);
  const auto log_uniform = [&](double lo, double hi) {
    return lo * std::pow(hi / lo, static_cast<double>(rng() >> 11) * 0x1.0p-53);
  };
  for (int trial = 0; trial < 200; ++trial) {
    QuadratureEncoder enc = encoder_in_counts(100);
    const bool half = (trial & 1) != 0;
    enc.placement = half ? EdgePlacement::HalfCount : EdgePlacement::WholeCount;
    const double start = static_cast<double>(static_cast<std::int64_t>(rng() % 2001) - 1000);
    const double counts = static_cast<double>(2 + rng() % 3000) * ((rng() & 1) != 0 ? 1.0 : -1.0);
    const double distance = counts + (half ? 0.5 : 0.0); // the end on the boundary
    MotionProfile p(start);
    const MoveLimits limits{log_uniform(10.0, 1e6), log_uniform(1.0, 1e7), log_uniform(1.0, 1e7)};
    const TrapezoidPlan plan = trapezoid_move(p, distance, limits);
    const QuadratureTrace trace = solve_quadrature(p, enc);
    ASSERT_FALSE(trace.edges.empty());
    const QuadEdge& last = trace.edges.back();
    ASSERT_EQ(last.count, enc.count_at(start + distance)) << "trial " << trial;
    const double tau_1 = std::sqrt(2.0 / plan.deceleration); // s, the last count before the end
    const bool ramp_holds_a_count = 0.5 * std::abs(plan.peak_velocity) * plan.decel_time.seconds() > 1.0;
    if (distance > 0) {
      EXPECT_EQ(last.time, p.end_time()) << "trial " << trial;
      if (ramp_holds_a_count && trace.edges.size() >= 2) {
        const double expected = static_cast<double>(p.end_time().count()) - tau_1 * 1e9;
        EXPECT_NEAR(static_cast<double>(trace.edges[trace.edges.size() - 2].time.count()), expected, 1.0)
            << "trial " << trial;
      }
    } else if (ramp_holds_a_count) {
      const double expected = static_cast<double>(p.end_time().count()) - tau_1 * 1e9;
      EXPECT_NEAR(static_cast<double>(last.time.count()), expected, 1.0) << "trial " << trial;
    }
  }
}
