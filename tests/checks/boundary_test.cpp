// Issue 16 items 4 and 5: one inclusive comparison rule for every limit, in exact units
// (integer ns for times; other values with rig::kCompareEpsilon), tested by sweeping a value
// across each limit with numbers that do not round exactly; and a check that judged nothing
// is an error, never a pass.

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "check_test_support.hpp"
#include "rig/checks/registry.hpp"
#include "rig/checks/shaft_move.hpp"
#include "rig/checks/word_bits.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using nlohmann::json;
using rig::Outcome;
using test::find;

PositionFn constant(double counts) {
  return [counts](Nanos) { return counts; };
}

TEST(Boundary, EdgeAtPositionIsInclusiveAtTheToleranceAfterRounding) {
  // Issue 16: 101.00000000000003 against 99..101 failed. One ulp over the limit is rounding,
  // not the board: it passes; a millionth of a count over fails.
  EdgeAtPositionSpec s;
  s.position = 100.0;
  s.tolerance = 1.0;
  const std::vector<Edge> out = {{1_ms, Level::High}};
  EXPECT_EQ(check_edge_at_position(out, constant(std::nextafter(101.0, 200.0)), {}, s).outcome(),
            Outcome::Pass);
  EXPECT_EQ(check_edge_at_position(out, constant(101.00000000000003), {}, s).outcome(), Outcome::Pass);
  // Tolerance 0.1 counts (not exact in binary), swept across both limits in 1e-6 count steps.
  s.tolerance = 0.1;
  for (int k = -3; k <= 3; ++k) {
    SCOPED_TRACE(k);
    const Outcome want = k <= 0 ? Outcome::Pass : Outcome::Fail;
    EXPECT_EQ(check_edge_at_position(out, constant(100.0 + 0.1 + k * 1e-6), {}, s).outcome(), want);
    EXPECT_EQ(check_edge_at_position(out, constant(99.9 - k * 1e-6), {}, s).outcome(), want);
  }
  // The same limit reached by sums that round differently.
  EXPECT_EQ(check_edge_at_position(out, constant(0.7 + 99.4), {}, s).outcome(), Outcome::Pass);
  EXPECT_EQ(check_edge_at_position(out, constant(100.3 - 0.2), {}, s).outcome(), Outcome::Pass);
}

TEST(Boundary, AdvanceCountsIsInclusiveAtTheTolerance) {
  AdvanceSpec s;
  s.setpoint = 100.3;
  s.advance_counts = 0.2; // expected 100.1, itself rounded
  s.tolerance = 0.1;
  const std::vector<Edge> out = {{1_ms, Level::High}};
  for (int k = -3; k <= 3; ++k) {
    SCOPED_TRACE(k);
    const Outcome want = k <= 0 ? Outcome::Pass : Outcome::Fail;
    EXPECT_EQ(check_advance(out, constant(100.2 + k * 1e-6), {}, s).outcome(), want);
    EXPECT_EQ(check_advance(out, constant(100.0 - k * 1e-6), {}, s).outcome(), want);
  }
}

// ans1 manual (seeds/000_08a2edf5547d4d1e.txt:572): master throughput 10 to 20 us. A limit
// written 20.3 us is 20'300 ns exactly; latencies are judged in whole ns.
TEST(Boundary, ThroughputLimitSweptInNanoseconds) {
  const auto p = std::get<ThroughputParams>(
      build_check_params(*find_check_kind("throughput"), "t",
                         json{{"output", "o"}, {"limit_us", 20.3}, {"crossings_us", {1000}}}));
  for (int d = -3; d <= 3; ++d) {
    SCOPED_TRACE(d);
    const std::vector<Edge> out = {{1_ms + 20'300_ns + Nanos{d}, Level::High}};
    const auto r = check_throughput(std::get<std::vector<Nanos>>(p.crossings), out, p.spec);
    EXPECT_EQ(find(r, "t.max").outcome, d <= 0 ? Outcome::Pass : Outcome::Fail);
    EXPECT_EQ(r.outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
  }
}

TEST(Boundary, ThroughputTimeoutIsInclusive) {
  // Issue 16: timeout_us was exclusive, so an edge exactly timeout after its crossing was
  // "missing". An edge at the timeout is in time; one ns later it is missing.
  const auto p = std::get<ThroughputParams>(build_check_params(
      *find_check_kind("throughput"), "t",
      json{{"output", "o"}, {"limit_us", 100}, {"timeout_us", 20.3}, {"crossings_us", {1000}}}));
  const std::vector<Nanos> crossings = {1_ms};
  for (int d = -2; d <= 2; ++d) {
    SCOPED_TRACE(d);
    const std::vector<Edge> out = {{1_ms + 20'300_ns + Nanos{d}, Level::High}};
    const auto r = check_throughput(crossings, out, p.spec);
    EXPECT_EQ(find(r, "t.missing").value, d <= 0 ? 0.0 : 1.0);
    EXPECT_EQ(r.outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
  }
}

TEST(Boundary, PulseWidthLimitsSweptInNanoseconds) {
  PulseWidthSpec s;
  s.min = 20'300_ns;
  s.max = 30'700_ns;
  for (int d = -3; d <= 3; ++d) {
    SCOPED_TRACE(d);
    const std::vector<Edge> shorter = {{1_ms, Level::High}, {1_ms + 20'300_ns - Nanos{d}, Level::Low}};
    EXPECT_EQ(check_pulse_width(shorter, s).outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
    const std::vector<Edge> longer = {{1_ms, Level::High}, {1_ms + 30'700_ns + Nanos{d}, Level::Low}};
    EXPECT_EQ(check_pulse_width(longer, s).outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
  }
}

// A pulse the run ends inside: one complete pulse of 25 us, then one that starts at 2 ms and is
// still on at the end. Open for up to max it is not judged (it might still end in time); a
// nanosecond over max it fails, already too long, on either level.
TEST(Boundary, PulseStillOpenAtTheEndFailsOnceOverMax) {
  PulseWidthSpec s;
  s.min = 20'300_ns;
  s.max = 30'700_ns;
  for (const Level level : {Level::High, Level::Low}) {
    s.level = level;
    const Level back = level == Level::High ? Level::Low : Level::High;
    const std::vector<Edge> line = {{1_ms, level}, {1_ms + 25_us, back}, {2_ms, level}};
    for (int d = -3; d <= 3; ++d) {
      SCOPED_TRACE(d);
      const auto r = check_pulse_width(line, s, 2_ms + 30'700_ns + Nanos{d});
      EXPECT_EQ(r.outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
      EXPECT_NEAR(find(r, "pulse.longest").value, d <= 0 ? 25.0 : (30'700 + d) / 1000.0, 1e-12);
    }
    // With no complete pulse the open one still fails (and the count says none was complete).
    const std::vector<Edge> stuck = {{2_ms, level}};
    const auto r = check_pulse_width(stuck, s, 500_ms);
    EXPECT_EQ(r.outcome(), Outcome::Fail);
    EXPECT_EQ(find(r, "pulse.longest").outcome, Outcome::Fail);
    s.min_pulses = 0;
    EXPECT_EQ(check_pulse_width(stuck, s, 500_ms).outcome(), Outcome::Fail);
    EXPECT_EQ(check_pulse_width(stuck, s, 2_ms + 30'700_ns).outcome(), Outcome::Error); // judged nothing
    s.min_pulses = 1;
  }
}

// The 4501's Cycle Output in mode 1 is on while a registration cycle runs, from Start to
// Latch (seeds/001 L7), each edge one throughput time (125 us, L281) after its input: Start at
// 1 ms, Latch at 3 ms give a pulse from 1.125 ms to 3.125 ms, 2000 us. With max_us 2000 and
// the run ending inside it, the pulse is no complete pulse and no missing edge: open up to
// max_us (end = 3.125 ms, the very instant it closes, is still open: the closing edge is
// after the end) the check judged nothing, an error; open 1 ns over max_us it already failed.
TEST(Boundary, PulseCutByTheEndIsAnErrorUntilItOutgrowsMax) {
  PulseWidthSpec s;
  s.min = 2000_us;
  s.max = 2000_us;
  const Nanos on = 1_ms + 125_us;
  const std::vector<Edge> open = {{on, Level::High}};
  for (int d = -2; d <= 2; ++d) {
    SCOPED_TRACE(d);
    const auto r = check_pulse_width(open, s, on + 2000_us + Nanos{d});
    EXPECT_EQ(r.outcome(), d <= 0 ? Outcome::Error : Outcome::Fail);
    if (d <= 0) {
      EXPECT_EQ(find(r, "pulse.count").detail.find("missing edge"), std::string::npos);
    } else {
      EXPECT_EQ(find(r, "pulse.longest").outcome, Outcome::Fail);
    }
  }
  // The run outlasts the pulse: 2000 us, exactly at both limits, passes.
  const std::vector<Edge> closed = {{on, Level::High}, {3_ms + 125_us, Level::Low}};
  EXPECT_EQ(check_pulse_width(closed, s, 3_ms + 200_us).outcome(), Outcome::Pass);
  // min_pulses 2 with one complete pulse and the second cut: the cut one may still count.
  s.min_pulses = 2;
  const std::vector<Edge> second = {
      {on, Level::High}, {3_ms + 125_us, Level::Low}, {5_ms + 125_us, Level::High}};
  EXPECT_EQ(find(check_pulse_width(second, s, 6_ms), "pulse.count").outcome, Outcome::Error);
  // ... but min_pulses 3: even if it closed, one pulse too few. A fail.
  s.min_pulses = 3;
  EXPECT_EQ(find(check_pulse_width(second, s, 6_ms), "pulse.count").outcome, Outcome::Fail);
  // A line never driven to the level has no pulse at all: a missing edge, a fail.
  s.min_pulses = 1;
  const auto never = check_pulse_width({}, s, 6_ms);
  EXPECT_EQ(never.outcome(), Outcome::Fail);
  EXPECT_NE(find(never, "pulse.count").detail.find("missing edge"), std::string::npos);
}

TEST(Boundary, DebounceBoundaryInclusiveAtFilterPlusTolerance) {
  DebounceSpec s{"d", 500_us, 300_ns}; // boundary in [499.7, 500.3] us
  for (int d = -3; d <= 3; ++d) {
    SCOPED_TRACE(d);
    const Nanos edge = 500'300_ns + Nanos{d};
    Bisection b;
    b.bracketed = true;
    b.rejected = edge - 1_ns;
    b.accepted = edge;
    b.probes = {{b.rejected, false}, {b.accepted, true}};
    EXPECT_EQ(find(check_debounce(b, s), "d.boundary").outcome, d <= 0 ? Outcome::Pass : Outcome::Fail);
  }
}

TEST(Boundary, ShaftMoveDurationSweptInNanoseconds) {
  ShaftMoveSpec s;
  s.from = 0_ms;
  s.duration_max = 6'100'000_ns; // duration_max_ms = 6.1
  for (int d = -2; d <= 2; ++d) {
    SCOPED_TRACE(d);
    const std::vector<Edge> step = {{1_ms, Level::High}, {6'100'000_ns + Nanos{d}, Level::Low}};
    EXPECT_EQ(check_shaft_move(step, {}, s).outcome(), d <= 0 ? Outcome::Pass : Outcome::Fail);
  }
}

// The SMD23E manual's trapezoid (seeds/003 L919-L928; steps/ms/s x 1000 = steps/s², L848-L851):
// v_s = 1000, v_p = 10000 steps/s, A = D = 100 steps/ms/s (a = d = 1e5 steps/s²), N = 4000,
// commanded at 0. Each ramp takes (v_p - v_s) / a = 90 ms and (v_p² - v_s²) / 2a = 495 steps;
// the cruise 3010 steps / v_p = 301 ms: T = 90 + 301 + 90 = 481 ms, the last step exactly at
// 481 ms. Step k falls where the position reaches k; `slow` stretches time (a slow clock).
std::vector<Edge> smd23e_trapezoid(double slow = 1.0) {
  constexpr double vs = 1000.0, vp = 10000.0, a = 1e5;
  std::vector<Edge> out;
  Level l = Level::Low;
  for (int k = 1; k <= 4000; ++k) {
    double t = 0.0;
    if (k <= 495) {
      t = (std::sqrt(vs * vs + 2.0 * a * k) - vs) / a;
    } else if (k <= 3505) {
      t = 0.090 + (k - 495) / vp;
    } else {
      t = 0.391 + (vp - std::sqrt(vp * vp - 2.0 * a * (k - 3505))) / a;
    }
    l = !l;
    out.push_back({Nanos{std::llround(t * slow * 1e9)}, l});
  }
  return out;
}

// The window's end swept across the move's last step (481 ms): at it the move is whole (the
// shaft then stands still to the run's end) and judged exactly; 1 ns before it the window cut
// the move, and its duration is not known (an error), unless it already ran past
// duration_max: with the profile (1 / v_s = 1 ms, L863) the last step 0.95 ms after the one
// before is the same move, at least 481 ms long, over a 480.999999 ms limit.
TEST(Boundary, ShaftMoveWindowEndSweptAcrossTheLastStep) {
  const std::vector<Edge> step = smd23e_trapezoid();
  ASSERT_EQ(step.back().time, 481_ms);
  const std::vector<Edge> dir = {{0_ms, Level::High}};
  const MoveProfile profile{
      .start = 0_ms, .starting_speed = 1000, .speed = 10000, .accel = 1e5, .decel = 1e5, .steps = 4000};
  for (const bool with_profile : {false, true}) {
    SCOPED_TRACE(with_profile);
    ShaftMoveSpec s;
    s.name = "m";
    s.to_given = true;
    if (with_profile) s.profile = profile;
    s.steps = 4000;
    s.duration_max = 481_ms;
    s.to = 481_ms;
    auto r = check_shaft_move(step, dir, s, 850_ms);
    EXPECT_EQ(r.outcome(), Outcome::Pass);
    EXPECT_EQ(find(r, "m.duration").value, 481.0);
    s.duration_max = 481_ms - 1_ns;
    EXPECT_EQ(find(check_shaft_move(step, dir, s, 850_ms), "m.duration").outcome, Outcome::Fail);
    s.to = 481_ms - 1_ns; // the last step falls 1 ns after the window
    // The window the campaign closed holds 3999 steps: a count, judged.
    EXPECT_EQ(find(check_shaft_move(step, dir, s, 850_ms), "m.steps").outcome, Outcome::Fail);
    s.steps.reset();
    s.duration_max = 481_ms;
    r = check_shaft_move(step, dir, s, 850_ms);
    EXPECT_EQ(find(r, "m.duration").outcome, Outcome::Error);
    EXPECT_EQ(r.outcome(), Outcome::Error);
    s.duration_max = 481_ms - 1_ns;
    r = check_shaft_move(step, dir, s, 850_ms);
    EXPECT_EQ(find(r, "m.duration").outcome, with_profile ? Outcome::Fail : Outcome::Error);
    if (with_profile) {
      EXPECT_EQ(find(r, "m.duration").value, 481.0); // to the next step, at least
    }
  }
}

// The run's end swept across the last step, no to_ms: the move is over only once the shaft
// stood still more than twice its step interval (here its slowest, the last, 0.954 ms) before
// the run ended; until then steps, duration, peak speed and reversals are errors.
TEST(Boundary, ShaftMoveRunEndSweptAcrossTheLastStep) {
  const std::vector<Edge> step = smd23e_trapezoid();
  const std::vector<Edge> dir = {{0_ms, Level::High}};
  const Nanos interval = step[3999].time - step[3998].time; // the slowest in the move
  ShaftMoveSpec s;
  s.name = "m";
  s.steps = 4000;
  s.duration_max = 481_ms;
  s.peak_min = 10000;
  s.reversals = 0;
  for (const Nanos end : {481_ms - 1_ns, 481_ms, 481_ms + 2 * interval}) {
    SCOPED_TRACE(end.count());
    s.to = end; // no to_ms: the window ends with the run
    const auto r = check_shaft_move(step, dir, s, end);
    EXPECT_EQ(r.outcome(), Outcome::Error);
    for (const char* m : {"m.steps", "m.duration", "m.peak_speed", "m.reversals"})
      EXPECT_EQ(find(r, m).outcome, Outcome::Error) << m;
  }
  s.to = 481_ms + 2 * interval + 1_ns;
  const auto r = check_shaft_move(step, dir, s, s.to);
  EXPECT_EQ(r.outcome(), Outcome::Pass);
  EXPECT_EQ(find(r, "m.duration").value, 481.0);
}

// A board 30 % slow (its move 625.3 ms) cut at 300 ms, by the run's end or by to_ms with the
// capture going on: its 289.9 ms seen is under 481 ms, so nothing is judged, never a pass. Cut
// at 500 ms it already ran 490+ ms: a fail. Speed already over peak_max, or a reversal more
// than allowed, fails too.
TEST(Boundary, ShaftMoveCutMoveFailsOnlyWhatIsAlreadyBeyond) {
  const std::vector<Edge> step = smd23e_trapezoid(1.3);
  const std::vector<Edge> dir = {{0_ms, Level::High}};
  ShaftMoveSpec s;
  s.name = "m";
  s.duration_max = 481_ms;
  s.to = 300_ms;
  EXPECT_EQ(check_shaft_move(step, dir, s, 300_ms).outcome(), Outcome::Error);
  s.to_given = true;
  EXPECT_EQ(check_shaft_move(step, dir, s, 850_ms).outcome(), Outcome::Error);
  s.to = 500_ms;
  EXPECT_EQ(check_shaft_move(step, dir, s, 850_ms).outcome(), Outcome::Fail);
  s.to = 850_ms;
  EXPECT_EQ(check_shaft_move(step, dir, s, 850_ms).outcome(), Outcome::Fail); // whole: 625.3 ms
  s.duration_max.reset();
  s.to = 300_ms;
  s.peak_max = 10000.0 / 1.3 - 1.0; // the slow board's cruise is 7692.3 steps/s
  EXPECT_EQ(check_shaft_move(step, dir, s, 850_ms).outcome(), Outcome::Fail);
  s.peak_max = 10000.0; // under it so far: a faster stretch may follow
  EXPECT_EQ(check_shaft_move(step, dir, s, 850_ms).outcome(), Outcome::Error);
}

TEST(Boundary, WordWithinLimitsComparedWithTheOneEpsilon) {
  // 0.1 * 3 is 0.30000000000000004: a limit written so is the same limit as 0.3.
  WordSpec s;
  s.observation = "w";
  s.upper = 0.1 * 3;
  s.lower = 0.1 * 3;
  EXPECT_EQ(check_word_within(std::vector<rig::Observation>{{"w", 0.3, "", 1_ms}}, s).outcome(),
            Outcome::Pass);
  EXPECT_EQ(check_word_within(std::vector<rig::Observation>{{"w", 0.300001, "", 1_ms}}, s).outcome(),
            Outcome::Fail);
  EXPECT_EQ(check_word_within(std::vector<rig::Observation>{{"w", 0.299999, "", 1_ms}}, s).outcome(),
            Outcome::Fail);
}

TEST(Boundary, TheRuleItself) {
  EXPECT_EQ(rig::judge(20'300_ns, std::nullopt, 20'300_ns), Outcome::Pass);
  EXPECT_EQ(rig::judge(20'301_ns, std::nullopt, 20'300_ns), Outcome::Fail);
  EXPECT_EQ(rig::judge(20'300_ns, 20'300_ns, std::nullopt), Outcome::Pass);
  EXPECT_EQ(rig::judge(20'299_ns, 20'300_ns, std::nullopt), Outcome::Fail);
  // The epsilon scales with the limit: at 10^6 counts one part in 10^12 is 10^-6 counts.
  EXPECT_EQ(rig::judge(1e6 + 5e-7, std::nullopt, 1e6), Outcome::Pass);
  EXPECT_EQ(rig::judge(1e6 + 2e-6, std::nullopt, 1e6), Outcome::Fail);
  EXPECT_EQ(rig::judge(std::nan(""), std::nullopt, std::nullopt), Outcome::Error);
  // A limit that is not a finite number judges nothing either: every comparison with NaN is
  // false, so it would pass any value.
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {std::nan(""), inf, -inf})
    for (const double v : {-1e9, 0.0, 1e9}) {
      EXPECT_EQ(rig::judge(v, bad, std::nullopt), Outcome::Error) << bad << " " << v;
      EXPECT_EQ(rig::judge(v, std::nullopt, bad), Outcome::Error) << bad << " " << v;
      EXPECT_EQ(rig::judge(v, 0.0, bad), Outcome::Error) << bad << " " << v;
    }
}

// The largest position a campaign can state: start_turns 10,000 (docs/campaigns.md) of a
// 10^6-line encoder, 4 * 10^10 counts. A tolerance window of +-0.5 counts there passes a value
// a few roundings beyond its end (what arithmetic on doubles of that size leaves) and fails a
// tenth of a count beyond, on both sides; a count of 1e-9 relative slack was 40 counts.
TEST(Boundary, CountsFarFromZeroKeepTheirTolerance) {
  const double expected = 4e10 + 70.0;
  const double lower = expected - 0.5;
  const double upper = expected + 0.5;
  double over = upper;
  double under = lower;
  for (int ulp = 0; ulp < 8; ++ulp) {
    EXPECT_EQ(rig::judge(over, lower, upper), Outcome::Pass) << ulp;
    EXPECT_EQ(rig::judge(under, lower, upper), Outcome::Pass) << ulp;
    over = std::nextafter(over, std::numeric_limits<double>::infinity());
    under = std::nextafter(under, -std::numeric_limits<double>::infinity());
  }
  for (const double beyond : {0.1, 0.5, 1.0, 31.24}) {
    EXPECT_EQ(rig::judge(upper + beyond, lower, upper), Outcome::Fail) << beyond;
    EXPECT_EQ(rig::judge(lower - beyond, lower, upper), Outcome::Fail) << beyond;
  }
}

// Item 5: a check that judged no measurement is an error, never a pass (the parser refuses
// these parameters; the checks stand on their own too).
TEST(JudgedNothing, ZeroMinimumsWithNothingCapturedAreErrors) {
  EdgeAtPositionSpec e;
  e.min_edges = 0;
  EXPECT_EQ(check_edge_at_position({}, constant(0.0), {}, e).outcome(), Outcome::Error);
  AdvanceSpec a;
  a.min_edges = 0;
  a.advance_counts = 0.0;
  EXPECT_EQ(check_advance({}, constant(0.0), {}, a).outcome(), Outcome::Error);
  PulseWidthSpec p;
  p.min_pulses = 0;
  EXPECT_EQ(check_pulse_width({}, p).outcome(), Outcome::Error);
  ThroughputSpec t;
  t.min_count = 0;
  t.limit = 20_us;
  EXPECT_EQ(check_throughput({}, {}, t).outcome(), Outcome::Error);
  FrameSpec f;
  f.min_frames = 0;
  EXPECT_EQ(check_frames_decode(
                {}, [](const RawFrame&) { return std::string(); }, f)
                .outcome(),
            Outcome::Error);
}

TEST(JudgedNothing, ThroughputWithNoCrossingIsAnErrorEvenWithMinCountOne) {
  ThroughputSpec t;
  t.limit = 20_us;
  const std::vector<Edge> out = {{1_ms, Level::High}};
  const auto r = check_throughput({}, out, t);
  EXPECT_EQ(r.outcome(), Outcome::Error);
  EXPECT_NE(r.measurements[0].detail.find("nothing judged"), std::string::npos);
  // The evidence keeps what it read and the least it asks for: 0 crossings, min_count.
  EXPECT_EQ(r.measurements[0].value, 0.0);
  EXPECT_EQ(r.measurements[0].lower, std::optional<double>(1.0));
  t.min_count = 100;
  EXPECT_EQ(check_throughput({}, out, t).measurements[0].lower, std::optional<double>(100.0));
}

TEST(JudgedNothing, WordBitsWithMaskZeroIsAnError) {
  WordSpec s;
  s.observation = "w";
  EXPECT_EQ(check_word_bits(std::vector<rig::Observation>{{"w", 0x1234, "", 1_ms}}, s, 0, 0).outcome(),
            Outcome::Error);
}

} // namespace
} // namespace hilrig::checks
