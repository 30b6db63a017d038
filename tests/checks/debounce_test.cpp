#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "check_test_support.hpp"
#include "rig/checks/check_params.hpp"
#include "rig/checks/debounce.hpp"
#include "rig/checks/registry.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

TEST(Bisection, FindsAKnownBoundaryWithinResolution) {
  // A board that accepts pulses of at least 1234.567 us. From [0, 10 ms] at 1 us resolution the
  // bracket halves from 10 ms to <= 1 us: 10000/2^14 = 0.61 us, so 14 probes plus the 2 ends.
  const Nanos boundary{1'234'567};
  int runs = 0;
  const auto b = bisect_boundary(
      [&](Nanos w) {
        ++runs;
        return w >= boundary;
      },
      0_ns, 10_ms, 1_us);
  ASSERT_TRUE(b.bracketed);
  EXPECT_GE(b.accepted, boundary);
  EXPECT_LT(b.rejected, boundary);
  EXPECT_LE(b.accepted - b.rejected, 1_us);
  EXPECT_EQ(runs, 16);
  EXPECT_EQ(b.probes.size(), 16U);
}

TEST(Bisection, PropertyBoundaryAlwaysInsideTheFinalBracket) {
  std::mt19937_64 rng(20261122);
  std::uniform_int_distribution<std::int64_t> pick(1, 50'000'000);
  for (int i = 0; i < 200; ++i) {
    const Nanos boundary{pick(rng)};
    const auto b = bisect_boundary([&](Nanos w) { return w >= boundary; }, 0_ns, 50_ms, 100_ns);
    ASSERT_TRUE(b.bracketed);
    EXPECT_LT(b.rejected, boundary);
    EXPECT_GE(b.accepted, boundary);
    EXPECT_LE(b.accepted - b.rejected, 100_ns);
  }
}

TEST(Bisection, UnbracketedWhenTheNarrowestProbeIsAccepted) {
  const auto b = bisect_boundary([](Nanos) { return true; }, 1_us, 1_ms, 1_us);
  EXPECT_FALSE(b.bracketed);
  EXPECT_EQ(b.probes.size(), 2U);
  const auto r = check_debounce(b, {.name = "in1", .filter = 500_us, .tolerance = 10_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "in1.boundary").detail.find("not bracketed"), std::string::npos);
}

// A hand-made bisection whose boundary (narrowest accepted) is `accepted`.
Bisection bracket(Nanos rejected, Nanos accepted) {
  return Bisection{true, rejected, accepted, {{rejected, false}, {accepted, true}}};
}

TEST(Debounce, BoundaryPassesAtFilterPlusToleranceAndFailsOneMicrosecondOrNanosecondBeyond) {
  // Filter 1000 us, tolerance 10 us: boundary allowed in [990, 1010] us.
  const DebounceSpec spec{.name = "in1", .filter = 1000_us, .tolerance = 10_us};
  EXPECT_EQ(check_debounce(bracket(1009_us, 1010_us), spec).outcome(), rig::Outcome::Pass);
  EXPECT_EQ(check_debounce(bracket(989_us, 990_us), spec).outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(check_debounce(bracket(1009_us, 1010_us), spec), "in1.boundary").value, 1010.0);
  for (const Nanos over : {1011_us, 1010_us + 1_ns}) {
    const auto r = check_debounce(bracket(over - 1_us, over), spec);
    EXPECT_EQ(find(r, "in1.boundary").outcome, rig::Outcome::Fail) << over.count();
  }
  EXPECT_EQ(find(check_debounce(bracket(988_us, 989_us), spec), "in1.boundary").outcome, rig::Outcome::Fail);
}

TEST(Debounce, AShortPulseAcceptedIsMisjudged) {
  // A 500 us pulse accepted although the filter is 1000 us (± 10): one misjudged probe.
  Bisection b = bracket(999_us, 1000_us);
  b.probes.push_back({500_us, true});
  const auto r = check_debounce(b, {.name = "in1", .filter = 1000_us, .tolerance = 10_us});
  EXPECT_EQ(find(r, "in1.misjudged").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "in1.misjudged").detail.find("500 us pulse was accepted"), std::string::npos);
}

// A scanning board: it takes a pulse starting at `start` when the pulse is still active at its
// first scan at least `filter` after the start, with scans at phase + k·scan. Its boundary at a
// start is filter + the time from the start to the next scan (0 .. scan - 1 ns) + `extra`.
struct ScanningBoard {
  Nanos scan;
  Nanos phase;
  Nanos filter;
  Nanos extra{0};
  [[nodiscard]] Nanos to_next_scan(Nanos start) const {
    const std::int64_t d = (phase - start).count() % scan.count();
    return Nanos{d < 0 ? d + scan.count() : d};
  }
  [[nodiscard]] bool accepts(Nanos start, Nanos width) const {
    return width >= filter + to_next_scan(start) + extra;
  }
};

// The shipped check's order: the limit probes, then bisection, at each start phase.
std::vector<PhaseBisection> bisect_all(const ScanningBoard& board, const DebounceParams& p, Nanos probe_at) {
  std::vector<PhaseBisection> out;
  const std::array<Nanos, 2> limits{p.spec.shortest_rejected(), p.spec.longest_accepted()};
  for (const Nanos start : p.probe_starts(probe_at))
    out.push_back({start, bisect_boundary([&](Nanos w) { return board.accepts(start, w); }, p.plan.narrow,
                                          p.plan.wide, p.plan.resolution, limits)});
  return out;
}

TEST(Bisection, LimitProbesFirstBracketABoardWithinTheLimits) {
  // Limits [990, 1010] us: 989.999 us rejected and 1010 us accepted bracket a 1000 us board, so
  // neither narrow nor wide is run; halving 20.001 us to <= 1 us takes 5 more probes.
  const std::array<Nanos, 2> limits{990_us - 1_ns, 1010_us};
  const auto b = bisect_boundary([](Nanos w) { return w >= 1000_us; }, 1_us, 5_ms, 1_us, limits);
  ASSERT_TRUE(b.bracketed);
  EXPECT_EQ(b.probes.size(), 7U);
  EXPECT_EQ(b.probes[0].width, 990_us - 1_ns);
  EXPECT_EQ(b.probes[1].width, 1010_us);
  EXPECT_GE(b.accepted, 1000_us);
  EXPECT_LT(b.rejected, 1000_us);
  // A board beyond a limit: the wide (or narrow) end is probed to bracket it.
  const auto late = bisect_boundary([](Nanos w) { return w >= 2_ms; }, 1_us, 5_ms, 1_us, limits);
  ASSERT_TRUE(late.bracketed);
  EXPECT_EQ(late.probes[2].width, 5_ms);
  EXPECT_GE(late.accepted, 2_ms);
  EXPECT_LT(late.rejected, 2_ms);
}

TEST(Bisection, ABoardThatRejectsAWiderPulseThanOneItTookHasNoBoundary) {
  const std::array<Nanos, 2> limits{990_us - 1_ns, 1010_us};
  const auto b = bisect_boundary([](Nanos w) { return w < 1_ms; }, 1_us, 5_ms, 1_us, limits);
  EXPECT_FALSE(b.bracketed);
  const auto r = check_debounce(b, {.name = "in1", .filter = 1000_us, .tolerance = 10_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "in1.boundary").detail.find("no single boundary"), std::string::npos);
}

// ans1 manual (seeds/000_08a2edf5547d4d1e.txt:1039-1040): sampling starts sixteen ms after the
// transition, and twelve of the sixteen samples must be applied: an application counts when it
// is still applied at the 12th sample, 27 ms after the transition on a board that samples at the
// transition itself, up to one 1 ms tick later on a board that sees it on its tick. The limit
// is [27, 28] ms at every start phase: filter 27.5 ms ± 0.5 ms. Here a board with the 1 ms tick
// whose boundary is 27 ms + the time to its next tick, probed at ten starts 0.1 ms apart: with
// its tick 0.9 ms after a start its boundaries at the probed starts run from 27.0 ms (a start on
// a tick) to 27.9 ms, so the check is given the limits [27.0, 27.9] ms the probed starts can
// show: exactly at both it passes; 1 ns beyond either fails (at the one start that shows it),
// whatever the board's tick phase (one per seed).
TEST(Debounce, EveryStartPhaseIsJudgedAndTheLimitsAreExactAtEach) {
  DebounceParams p;
  p.spec = {.name = "brake", .filter = 27'450_us, .tolerance = 450_us};
  p.plan = BisectionPlan{5_ms, 60_ms, 100_us};
  p.phase = PhaseScan{1_ms, 10};
  p.probe_phases = 10;
  const Nanos probe_at = 100'500_us;
  for (std::uint64_t seed : {0U, 3U, 7U, 9U}) {
    // The board's tick on a probed start: start k = seed % 10 (a start on a tick, boundary
    // 27.0 ms), and start k + 1 is 0.1 ms after a tick (boundary 27.9 ms).
    const Nanos tick_phase = probe_at + 100_us * static_cast<std::int64_t>(seed % 10);
    for (const std::int64_t extra : {-1, 0, 1}) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << " extra " << extra << " ns");
      const ScanningBoard board{1_ms, tick_phase, 27_ms, Nanos{extra}};
      const auto phases = bisect_all(board, p, probe_at);
      ASSERT_EQ(phases.size(), 10U);
      const auto r = check_debounce(phases, p.spec);
      EXPECT_EQ(r.outcome(), extra == 0 ? rig::Outcome::Pass : rig::Outcome::Fail);
      EXPECT_EQ(find(r, "brake.misjudged").value, extra == 0 ? 0.0 : 1.0);
      const auto& boundary = find(r, "brake.boundary");
      EXPECT_EQ(boundary.outcome, extra == 0 ? rig::Outcome::Pass : rig::Outcome::Fail);
      if (extra > 0) {
        EXPECT_GT(boundary.value, 27'900.0); // the late start's boundary
      } else if (extra < 0) {
        EXPECT_LT(boundary.value, 27'000.0); // the start on a tick
      }
      for (const auto& ph : phases) {
        EXPECT_GE(ph.bisection.accepted, 27_ms + board.to_next_scan(ph.start) + Nanos{extra});
        EXPECT_LT(ph.bisection.rejected, 27_ms + board.to_next_scan(ph.start) + Nanos{extra});
      }
    }
  }
}

TEST(Debounce, OnePhaseWithinTheLimitsDoesNotHideAnotherBeyond) {
  // Nine starts at 27.5 ms and one at 28.001 ms: the worst phase decides, and is named.
  DebounceSpec spec{.name = "b", .filter = 27'500_us, .tolerance = 500_us};
  std::vector<PhaseBisection> phases;
  for (int k = 0; k < 10; ++k) {
    const Nanos boundary = k == 6 ? 28'001_us : 27'500_us;
    phases.push_back({100'500_us + 100_us * k, bracket(boundary - 1_us, boundary)});
  }
  const auto r = check_debounce(phases, spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_EQ(find(r, "b.boundary").value, 28'001.0);
  EXPECT_NE(find(r, "b.boundary").detail.find("starting at 101.1 ms"), std::string::npos);
  EXPECT_NE(find(r, "b.boundary").detail.find("from 27500 us to 28001 us"), std::string::npos);
}

TEST(Debounce, ProbeStartsSpreadOverTheScanAndCoverEveryBin) {
  DebounceParams p;
  p.phase = PhaseScan{1_ms, 10};
  p.probe_phases = 10;
  const auto starts = p.probe_starts(100'500_us);
  ASSERT_EQ(starts.size(), 10U);
  for (std::size_t k = 0; k < starts.size(); ++k)
    EXPECT_EQ(starts[k], 100'500_us + 100_us * static_cast<std::int64_t>(k));
  // Seven phases of a 1 ms scan: floor(k·1 ms / 7), each in its own bin of 7.
  p.phase = PhaseScan{1_ms, 7};
  p.probe_phases = 7;
  EXPECT_EQ(p.probe_starts(0_ns)[3], Nanos{428'571});
  // No scan: one phase, at probe_at.
  DebounceParams one;
  EXPECT_EQ(one.probe_starts(5_ms), std::vector<Nanos>{5_ms});
}

} // namespace
} // namespace hilrig::checks
