// Quadrature faults: each one is either caught by the decoder (illegal transitions) or
// visibly changes the decoded count, or is caught by the edge-spacing checks. The base
// signal is 1,000 counts/s for 20 ms: X4 edges at 0.5, 1.5, ... 19.5 ms into states
// 1 ... 20 (A edges at 0.5 + 2k ms, B edges at 1.5 + 2k ms).

#include "signals/edge_rate.hpp"
#include "signals/move_builders.hpp"
#include "signals/quadrature_decoder.hpp"
#include "signals/quadrature_faults.hpp"
#include "signals/quadrature_replay.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

namespace {

QuadratureTrace base_trace() {
  QuadratureEncoder enc;
  enc.lines_per_turn = 1024;
  enc.units_per_turn = 4096.0; // profile in counts
  MotionProfile p;
  constant_speed(p, 1'000.0, 20_ms);
  return solve_quadrature(p, enc);
}

struct Decoded {
  std::int64_t final_count = 0;
  std::uint64_t illegal = 0;
  bool ever_wrong = false; // decoded count differed from the true count at some instant
};

Decoded decode(const QuadratureTrace& trace) {
  QuadratureDecoder d(CountMode::X4, trace.initial_level(QuadChannel::A),
                      trace.initial_level(QuadChannel::B));
  d.set_count(trace.initial_count);
  Decoded out;
  std::size_t i = 0;
  replay(trace, d, [&](Nanos t, const QuadratureDecoder& dec) {
    std::int64_t truth = trace.initial_count;
    for (; i < trace.edges.size() && trace.edges[i].time <= t; ++i) truth = trace.edges[i].count;
    if (dec.count() != truth) out.ever_wrong = true;
  });
  out.final_count = d.count();
  out.illegal = d.illegal_transitions();
  return out;
}

std::vector<QuadEdge> channel(const QuadratureTrace& t, QuadChannel ch) {
  std::vector<QuadEdge> out;
  for (const QuadEdge& e : t.edges)
    if (e.channel == ch) out.push_back(e);
  return out;
}

} // namespace

TEST(QuadratureFaults, CleanSignalDecodesExactly) {
  const Decoded d = decode(base_trace());
  EXPECT_EQ(d.final_count, 20);
  EXPECT_EQ(d.illegal, 0U);
  EXPECT_FALSE(d.ever_wrong);
  EXPECT_FALSE(first_spacing_violation(base_trace(), 250e3).has_value());
}

TEST(QuadratureFaults, GlitchShowsInTheCountAndTheEdgeSpacing) {
  // At 2.2 ms the state is 2 (A = B = 1). A 100 ns low pulse on A reads as one count
  // forward (11 -> 01) and back: the count is wrong for 100 ns, right again after.
  QuadratureTrace t = base_trace();
  inject_glitch(t, QuadChannel::A, 2'200_us, 100_ns);
  const Decoded d = decode(t);
  EXPECT_TRUE(d.ever_wrong);
  EXPECT_EQ(d.final_count, 20);
  // Two A edges 100 ns apart: 1 / (2 x 100 ns) = 5 MHz, far above 250 kHz.
  const auto v = first_spacing_violation(t, 250e3);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->channel, QuadChannel::A);
  EXPECT_EQ(v->time, 2'200'100_ns);
  EXPECT_EQ(v->spacing, 100_ns);
  EXPECT_DOUBLE_EQ(v->channel_hz, 5e6);
}

TEST(QuadratureFaults, GlitchAcrossARealEdgeInvertsIt) {
  // B rises at 1.5 ms. Inverting B over [1.4, 1.6) ms: B rises early at 1.4, the real
  // rise becomes a fall at 1.5 and B rises again at 1.6 ms.
  QuadratureTrace t = base_trace();
  inject_glitch(t, QuadChannel::B, 1'400_us, 200_us);
  const auto b = channel(t, QuadChannel::B);
  ASSERT_GE(b.size(), 4U);
  EXPECT_EQ(b[0].time, 1'400_us);
  EXPECT_EQ(b[0].level, Level::High);
  EXPECT_EQ(b[1].time, 1'500_us);
  EXPECT_EQ(b[1].level, Level::Low);
  EXPECT_EQ(b[2].time, 1'600_us);
  EXPECT_EQ(b[2].level, Level::High);
  EXPECT_EQ(b[3].time, 3'500_us);
  EXPECT_EQ(b[3].level, Level::Low);
}

TEST(QuadratureFaults, MissingEdgeLosesCounts) {
  // Edge 4 is A rising at 4.5 ms; its pulse goes (A's fall at 6.5 ms too). The B edges at
  // 5.5 and 7.5 ms then read backwards then forwards: 4 counts lost, 16 instead of 20.
  QuadratureTrace t = base_trace();
  ASSERT_EQ(t.edges[4].channel, QuadChannel::A);
  inject_missing_edge(t, 4);
  EXPECT_EQ(t.edges.size(), 18U);
  const Decoded d = decode(t);
  EXPECT_EQ(d.final_count, 16);
  EXPECT_TRUE(d.ever_wrong);
}

TEST(QuadratureFaults, SimultaneousEdgesAreIllegal) {
  // A rises at 4.5 ms (state 4 = 00 -> 10); B's rise moves from 5.5 to 4.5 ms: 00 -> 11,
  // illegal, so those two edges count nothing; the 14 edges from 6.5 ms on decode
  // normally: 4 + 14 = 18 instead of 20.
  QuadratureTrace t = base_trace();
  inject_simultaneous_edges(t, 4);
  const Decoded d = decode(t);
  EXPECT_EQ(d.illegal, 1U);
  EXPECT_EQ(d.final_count, 18);
}

TEST(QuadratureFaults, NoiseBurstIsReproducibleAndVisible) {
  NoiseBurst burst{10_ms, 10_us, 8, 20_ns, 200_ns, 42};
  QuadratureTrace t1 = base_trace();
  QuadratureTrace t2 = base_trace();
  QuadratureTrace t3 = base_trace();
  inject_noise_burst(t1, burst);
  inject_noise_burst(t2, burst);
  burst.seed = 43;
  inject_noise_burst(t3, burst);
  EXPECT_EQ(t1.edges, t2.edges);
  EXPECT_NE(t1.edges, t3.edges);
  // Every added edge lies inside the burst (start + length + max width).
  const QuadratureTrace clean = base_trace();
  std::size_t added = 0;
  for (const QuadEdge& e : t1.edges) {
    bool original = false;
    for (const QuadEdge& c : clean.edges) original = original || c == e;
    if (original) continue;
    ++added;
    EXPECT_GE(e.time, 10_ms);
    EXPECT_LE(e.time, 10_ms + 10_us + 200_ns);
  }
  EXPECT_GT(added, 0U);
  EXPECT_TRUE(decode(t1).ever_wrong);
  EXPECT_TRUE(first_spacing_violation(t1, 250e3).has_value());
}

TEST(QuadratureFaults, PhaseErrorNarrowsThenBreaksQuadrature) {
  // Clean: 1 ms between every A and B edge (a quarter period at 1,000 counts/s).
  EXPECT_EQ(min_phase_separation(base_trace()), 1_ms);
  // B shifted by half a quarter period: 0.5 ms to the next A edge; counts still right.
  QuadratureTrace half = base_trace();
  inject_phase_error(half, 0.5);
  EXPECT_EQ(min_phase_separation(half), 500_us);
  EXPECT_EQ(decode(half).final_count, 20);
  // A whole quarter: B changes with A, the decoder flags illegal transitions.
  QuadratureTrace quarter = base_trace();
  inject_phase_error(quarter, 1.0);
  EXPECT_GT(decode(quarter).illegal, 0U);
  // Beyond: B lags A by more than a quarter, i.e. leads the next A edge: reads as reverse.
  QuadratureTrace beyond = base_trace();
  inject_phase_error(beyond, 1.5);
  EXPECT_LT(decode(beyond).final_count, 0);
}
