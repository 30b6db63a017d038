// The quadrature waveform (signals/quadrature_waveform.hpp) against the edge stream it stands
// for: under random motion (trapezoids, ramps through zero, pauses, reversals), the count at
// every edge instant and 1 ns either side, the count the lines show between the edges of one
// instant, and the first time the count leaves a range, each equal to what replaying the
// solver's edges gives. Asked in time order, forgetting behind, as a sampling model asks.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_waveform.hpp"
#include "tests/signals/random_motion.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

QuadratureEncoder counts_encoder() {
  QuadratureEncoder e; // the rig's: a profile in counts, count = floor(position)
  e.lines_per_turn = 1024;
  e.units_per_turn = static_cast<double>(e.counts_per_turn());
  e.placement = EdgePlacement::WholeCount;
  return e;
}

// Replaying the edges: the count after every edge at or before t.
std::int64_t replay_count(const QuadratureTrace& trace, Nanos t) {
  const auto it = std::upper_bound(trace.edges.begin(), trace.edges.end(), t,
                                   [](Nanos time, const QuadEdge& e) { return time < e.time; });
  return it == trace.edges.begin() ? trace.initial_count : std::prev(it)->count;
}

// Replaying the edges: the first one after t whose count is outside [lo, hi].
Nanos replay_leave(const QuadratureTrace& trace, Nanos t, std::int64_t lo, std::int64_t hi) {
  auto it = std::upper_bound(trace.edges.begin(), trace.edges.end(), t,
                             [](Nanos time, const QuadEdge& e) { return time < e.time; });
  for (; it != trace.edges.end(); ++it)
    if (it->count < lo || it->count > hi) return it->time;
  return Nanos::max();
}

TEST(QuadratureWaveform, CountAndLeaveTimeAreWhatReplayingTheEdgesGives) {
  constexpr Nanos kEnd = 300_ms;
  std::size_t edges_checked = 0;
  std::size_t leaves_found = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    const MotionProfile profile = testing::random_motion(seed, kEnd);
    const QuadratureTrace trace = solve_quadrature(profile, counts_encoder(), kEnd);
    QuadratureWaveform waveform(profile, counts_encoder(), kEnd);
    std::mt19937_64 rng(seed);
    const auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Nanos last{-1};
    for (std::size_t i = 0; i < trace.edges.size(); i += static_cast<std::size_t>(pick(1, 7))) {
      const Nanos t = trace.edges[i].time;
      if (t == last) continue;
      last = t;
      for (const Nanos at : {t - 1_ns, t, t + 1_ns}) {
        ASSERT_EQ(waveform.count_at(at), replay_count(trace, at)) << at.count() << " ns";
        const std::int64_t c = replay_count(trace, at);
        const std::int64_t lo = c - pick(0, 40);
        const std::int64_t hi = c + pick(0, 40);
        const Nanos leave = waveform.leaves(at, lo, hi);
        ASSERT_EQ(leave, replay_leave(trace, at, lo, hi)) << at.count() << " ns [" << lo << ", " << hi << "]";
        leaves_found += leave != Nanos::max() ? 1U : 0U;
      }
      // Between the edges of one instant: the lines show the count after each of them.
      std::int64_t shown = replay_count(trace, t - 1_ns);
      for (std::size_t k = i; k < trace.edges.size() && trace.edges[k].time == t; ++k) {
        ASSERT_EQ(waveform.count_showing(t, channel_a(shown), channel_b(shown)), shown);
        shown = trace.edges[k].count;
      }
      ASSERT_EQ(waveform.count_showing(t, channel_a(shown), channel_b(shown)), shown);
      waveform.forget_before(t); // a sampling model forgets what lies behind its last scan
      ++edges_checked;
    }
    EXPECT_EQ(waveform.leaves(kEnd, trace.edges.empty() ? 0 : trace.edges.back().count,
                              trace.edges.empty() ? 0 : trace.edges.back().count),
              Nanos::max()); // no edge after the end
  }
  EXPECT_GT(edges_checked, 10'000U); // the motion moved
  EXPECT_GT(leaves_found, 10'000U);
}

TEST(QuadratureWaveform, LevelsNoCountAtTheInstantShowsAreAnError) {
  MotionProfile p(0.5);
  p.cruise(1_ms); // at rest: count 0, A and B low
  QuadratureWaveform waveform(p, counts_encoder(), 1_ms);
  EXPECT_EQ(waveform.count_showing(500_us, false, false), 0);
  EXPECT_THROW((void)waveform.count_showing(500_us, true, true), std::logic_error);
  EXPECT_EQ(waveform.leaves(0_ns, 0, 0), Nanos::max());
}

} // namespace
} // namespace hilrig::signals
