#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "check_test_support.hpp"
#include "rig/checks/brake.hpp"
#include "rig/checks/brake_application.hpp"
#include "rig/checks/standstill.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

// The shaft counts every 10 ms until `stop`, then stays at its last count; the capture ends
// at 600 ms. Brake applied at 100 ms.
std::vector<PositionSample> shaft_stopping_at(Nanos stop) {
  std::vector<PositionSample> s;
  double count = 0.0;
  for (Nanos t = 0_ms; t < stop; t += 10_ms) s.push_back({t, count++});
  s.push_back({stop, count});
  return s;
}

// A shaft that moves, stops, creeps back and stops again (counts every ms, with long still
// stretches), compacted by append_motion: the standstill is the same as from every sample.
TEST(BrakeStop, CompactedMotionGivesTheSameStandstill) {
  std::vector<PositionSample> all;
  std::vector<PositionSample> kept;
  const double counts[] = {0, 1, 2, 2, 2, 3, 3, 2, 2, 2, 2, 5, 5, 5, 5, 5, 5, 5};
  Nanos t = 0_ms;
  for (const double c : counts) {
    all.push_back({t, c});
    append_motion(kept, {t, c});
    t += 1_ms;
  }
  EXPECT_LE(kept.size(), 4U);
  // The last change is to 5 at 11 ms; the samples run to 17 ms.
  for (const Nanos from : {0_ms, 5_ms, 11_ms, 12_ms, 17_ms, 20_ms}) {
    for (const Nanos end : {10_ms, 17_ms, 30_ms}) {
      EXPECT_EQ(standstill_after(kept, from, end), standstill_after(all, from, end))
          << "from " << from.count() << " end " << end.count();
    }
  }
  EXPECT_EQ(standstill_after(kept, 5_ms, 30_ms), 11_ms);
}

TEST(BrakeStop, CompactedMotionKeepsAShortTraceWhole) {
  std::vector<PositionSample> kept;
  append_motion(kept, {0_ms, 4.0});
  append_motion(kept, {1_ms, 5.0});
  ASSERT_EQ(kept.size(), 2U);
  EXPECT_EQ(kept[0].time, 0_ms);
  EXPECT_EQ(kept[0].position, 4.0);
  EXPECT_EQ(kept[1].time, 1_ms);
  EXPECT_EQ(kept[1].position, 5.0);
}

TEST(BrakeStop, StandstillIsTheLastCountChange) {
  const auto s = shaft_stopping_at(300_ms);
  EXPECT_EQ(standstill_after(s, 100_ms, 600_ms), 300_ms);
  // Nothing after the last change proves it stayed: no standstill.
  EXPECT_EQ(standstill_after(s, 100_ms, 300_ms), std::nullopt);
  // Already still before the brake: standstill at the brake instant.
  EXPECT_EQ(standstill_after(s, 400_ms, 600_ms), 400_ms);
}

Standstill exactly_at(Nanos t) { return Standstill{t, t}; }

TEST(BrakeStop, PassesAtTheLimitAndFailsOneMillisecondOrOneNanosecondOver) {
  // Applied 100 ms, exact standstill 300 ms: 200 ms stop time.
  const BrakeSpec spec{.name = "brake", .limit = 200_ms};
  auto r = check_brake_stop(100_ms, exactly_at(300_ms), Nanos::max(), {}, spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "brake.stop_time").value, 200.0);
  EXPECT_EQ(find(r, "brake.stop_time").unit, "ms");
  ASSERT_TRUE(find(r, "brake.stop_time").window);
  EXPECT_EQ(find(r, "brake.stop_time").window->end, 300_ms);
  for (const Nanos stop : {301_ms, 300_ms + 1_ns}) {
    r = check_brake_stop(100_ms, exactly_at(stop), Nanos::max(), {}, spec);
    EXPECT_EQ(r.outcome(), rig::Outcome::Fail) << stop.count();
  }
}

// From count changes alone (hardware): the shaft counts every 10 ms and its last change is
// at 300 ms, so it is no faster than 1 count / 10 ms after it and has stopped by 310 ms:
// standstill in [300, 310] ms, a stop time of 200 .. 210 ms judged on 210 ms.
TEST(BrakeStop, FromCountChangesTheIntervalIsJudgedOnItsUpperEnd) {
  const auto motion = shaft_stopping_at(300_ms);
  const auto still = standstill_interval(motion, 100_ms, 600_ms);
  ASSERT_TRUE(still);
  EXPECT_EQ(still->earliest, 300_ms);
  EXPECT_EQ(still->latest, 310_ms);
  for (const auto& [limit, outcome] :
       {std::pair{209_ms, rig::Outcome::Fail}, std::pair{210_ms - 1_ns, rig::Outcome::Fail},
        std::pair{210_ms, rig::Outcome::Pass}, std::pair{211_ms, rig::Outcome::Pass}}) {
    const auto r = check_brake_stop(100_ms, motion, 600_ms, {}, {.name = "b", .limit = limit});
    EXPECT_EQ(find(r, "b.stop_time").outcome, outcome) << limit.count();
    EXPECT_EQ(find(r, "b.stop_time").value, 210.0);
    EXPECT_NE(find(r, "b.stop_time").detail.find("judged on the upper end"), std::string::npos);
  }
  // The interval must end inside the trace to prove the shaft stayed still.
  EXPECT_EQ(standstill_interval(motion, 100_ms, 305_ms), std::nullopt);
  // Already still before the brake: [from, from].
  EXPECT_EQ(standstill_interval(motion, 400_ms, 600_ms)->latest, 400_ms);
}

TEST(BrakeStop, ExactStandstillPastTheTraceIsNoStandstill) {
  EXPECT_EQ(exact_standstill(601_ms, 600_ms), std::nullopt);
  EXPECT_EQ(exact_standstill(std::nullopt, 600_ms), std::nullopt);
  EXPECT_EQ(exact_standstill(600_ms, 600_ms)->latest, 600_ms);
}

// Still moving when the trace ends 500 ms after the brake: the stop is longer than 500 ms,
// over a 500 ms limit for certain (a fail); against 500 ms + 1 ns it may still end within it,
// so the cut stop is not judged (an error), never a fail of a board that may be in spec.
TEST(BrakeStop, StillMovingAtTheEndOfTheTraceFailsOnlyPastTheLimit) {
  const auto r =
      check_brake_stop(100_ms, shaft_stopping_at(600_ms), 600_ms, {}, {.name = "b", .limit = 500_ms});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "b.stop_time").detail.find("no standstill"), std::string::npos);
  const auto cut =
      check_brake_stop(100_ms, shaft_stopping_at(600_ms), 600_ms, {}, {.name = "b", .limit = 500_ms + 1_ns});
  EXPECT_EQ(cut.outcome(), rig::Outcome::Error);
  EXPECT_NE(find(cut, "b.stop_time").detail.find("nothing judged"), std::string::npos);
  EXPECT_EQ(check_brake_stop(100_ms, std::nullopt, 600_ms, {}, {.name = "b", .limit = 500_ms}).outcome(),
            rig::Outcome::Fail);
  EXPECT_EQ(
      check_brake_stop(100_ms, std::nullopt, 600_ms, {}, {.name = "b", .limit = 500_ms + 1_ns}).outcome(),
      rig::Outcome::Error);
}

TEST(BrakeStop, ReportedStopTimeAgainstMeasured) {
  // ANS1 W-17: the stop timer reads 275 ms at detection; reported = 275 - 125 = 150 ms. The
  // shaft stopped 150 ms after the brake: agrees. Tolerance 2 ms: 148 passes, 147.9 fails.
  BrakeSpec spec{.name = "b", .limit = 200_ms, .reported_ms = 275.0 - 125.0};
  const auto motion = shaft_stopping_at(250_ms);
  EXPECT_EQ(check_brake_stop(100_ms, motion, 600_ms, {}, spec).outcome(), rig::Outcome::Pass);
  spec.reported_ms = 148.0;
  EXPECT_EQ(check_brake_stop(100_ms, motion, 600_ms, {}, spec).outcome(), rig::Outcome::Pass);
  spec.reported_ms = 147.9;
  const auto r = check_brake_stop(100_ms, motion, 600_ms, {}, spec);
  EXPECT_EQ(find(r, "b.reported").outcome, rig::Outcome::Fail);
}

TEST(BrakeStop, FaultOutputMustAssertExactlyWhenTheLimitIsExceeded) {
  // Fault output normally high, low = fault ([MODEL], ANS1 chapter 3). Stop time 200 ms.
  const auto motion = exactly_at(300_ms);
  const std::vector<Edge> fault{{300_ms + 125_ms, Level::Low}};
  const std::vector<Edge> none;
  BrakeSpec spec{.name = "b", .limit = 150_ms, .check_fault = true};
  // Over the limit: the fault must assert.
  EXPECT_EQ(find(check_brake_stop(100_ms, motion, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, motion, Nanos::max(), none, spec), "b.fault_output").outcome,
            rig::Outcome::Fail);
  // Exactly at the limit: no fault expected; one asserted is a failure.
  spec.limit = 200_ms;
  EXPECT_EQ(find(check_brake_stop(100_ms, motion, Nanos::max(), none, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, motion, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Fail);
}

// An interval that straddles the limit (stop time 200 .. 210 ms, limit 205 ms) cannot say
// whether the board had to assert its fault: either answer passes, the stop time fails.
TEST(BrakeStop, FaultOutputFromAnIntervalAcrossTheLimitAcceptsEither) {
  const Standstill still{300_ms, 310_ms};
  const std::vector<Edge> fault{{400_ms, Level::Low}};
  const BrakeSpec spec{.name = "b", .limit = 205_ms, .check_fault = true};
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), {}, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), {}, spec), "b.stop_time").outcome,
            rig::Outcome::Fail);
}

// ans1 manual (seeds/000_08a2edf5547d4d1e.txt:1042, 1052, 640): the board takes the shaft as
// stopped when its count has not changed for 125 ms and reports that instant - 125 ms, on its
// 1 ms tick, timed from its tick that saw the brake applied. So its report counts whole ticks
// from a tick in [applied, applied + 1 ms) to a tick in [last change, last change + 1 ms):
// brake applied at 100 ms, last count change at 240.3 ms, standstill at 247.9 ms gives the
// window [240.3 - 100 - 1, 247.9 - 100 + 1] = [139.3, 148.9] ms. Inclusive at both ends, and
// 1 ns beyond either end fails.
TEST(BrakeStop, ReportedStopTimeIsJudgedAgainstTheWindowACorrectBoardCanReport) {
  const Standstill still{247_ms + 900_us, 247_ms + 900_us, 240_ms + 300_us};
  BrakeSpec spec{.name = "b", .limit = 150_ms, .report_tick = 1_ms};
  const auto w = report_window(100_ms, still, 1_ms);
  EXPECT_DOUBLE_EQ(w.low_ms, 139.3);
  EXPECT_DOUBLE_EQ(w.high_ms, 148.9);
  for (const auto& [reported, outcome] :
       {std::pair{139.3, rig::Outcome::Pass}, std::pair{139.3 - 1e-6, rig::Outcome::Fail},
        std::pair{148.9, rig::Outcome::Pass}, std::pair{148.9 + 1e-6, rig::Outcome::Fail},
        std::pair{140.0, rig::Outcome::Pass}, std::pair{148.0, rig::Outcome::Pass},
        std::pair{139.0, rig::Outcome::Fail}, std::pair{149.0, rig::Outcome::Fail}}) {
    spec.reported_ms = reported;
    const auto r = check_brake_stop(100_ms, still, Nanos::max(), {}, spec);
    EXPECT_EQ(find(r, "b.reported").outcome, outcome) << reported;
    EXPECT_NE(find(r, "b.reported").detail.find("[139.3, 148.9] ms"), std::string::npos)
        << find(r, "b.reported").detail;
  }
  // A shaft already still when the brake is applied: the board reports 0 (its first window
  // after the application holds no change), so the window starts at -1 tick, not before.
  const Standstill before{90_ms, 90_ms, 80_ms};
  // A board that saw the application through a later closing of its bounce (0.6 ms on)
  // starts its timer that much later: its report may be that much shorter.
  EXPECT_DOUBLE_EQ(report_window(100_ms, before, 1_ms, 600_us).low_ms, -1.6);
  EXPECT_DOUBLE_EQ(report_window(100_ms, before, 1_ms, 600_us).high_ms, 1.0);
  EXPECT_DOUBLE_EQ(report_window(100_ms, before, 1_ms).low_ms, -1.0);
  EXPECT_DOUBLE_EQ(report_window(100_ms, before, 1_ms).high_ms, 1.0);
  // On hardware (an interval from count changes) the window runs from the interval's lower
  // end, the last change, to its upper end: conservative, no correct board fails.
  const Standstill interval{300_ms, 310_ms};
  EXPECT_DOUBLE_EQ(report_window(100_ms, interval, 1_ms).low_ms, 199.0);
  EXPECT_DOUBLE_EQ(report_window(100_ms, interval, 1_ms).high_ms, 211.0);
}

// The board decides its overrun from its own report (L1052, CB8 w5): with the report window
// [139.3, 148.9] ms against a 145 ms limit either answer is right; against 139 ms (the whole
// window over) the fault must assert, against 149 ms (the whole window within) it must not.
TEST(BrakeStop, WithTheBoardsTickTheFaultOutputIsExpectedFromTheReportWindow) {
  const Standstill still{247_ms + 900_us, 247_ms + 900_us, 240_ms + 300_us};
  const std::vector<Edge> fault{{400_ms, Level::Low}};
  const std::vector<Edge> none;
  BrakeSpec spec{.name = "b", .limit = 145_ms, .report_tick = 1_ms, .check_fault = true};
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), none, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  spec.limit = 139_ms;
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), none, spec), "b.fault_output").outcome,
            rig::Outcome::Fail);
  spec.limit = 149_ms;
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), fault, spec), "b.fault_output").outcome,
            rig::Outcome::Fail);
  EXPECT_EQ(find(check_brake_stop(100_ms, still, Nanos::max(), none, spec), "b.fault_output").outcome,
            rig::Outcome::Pass);
}

// The ANS1's brake debounce (manual L1038-L1040): a transition to "applied" (low) starts a
// cycle; 16 samples 1 ms apart from 16 ms after it; 8 released samples abort it; at 32 ms,
// fewer than 12 applied samples abort it. The board checks its input on a 1 ms tick of unknown
// phase: it starts the cycle at its first tick after the transition, t0 = transition + d with
// d in [0, 1 ms). An application pulse of width w holds sample k applied when 16 + k + d < w:
// 12 applied samples need w > 27 ms + d. So w <= 27 ms is noise on every board, w >= 28 ms
// qualifies on every board, and between them the tick's phase decides: nothing certain.
std::vector<Edge> pulse_low(Nanos at, Nanos width) { return {{at, Level::Low}, {at + width, Level::High}}; }

BrakeApplication ans1(const std::vector<Edge>& line, Nanos end = 1'000_ms) {
  return brake_application(line, Level::High, Level::Low, 0_ms, end, BrakeDebounce::Ans1);
}

TEST(BrakeApplication, Ans1QualifiesAPulseOf28MsOnEveryTickPhase) {
  for (const Nanos at : {100_ms, 100'500'000_ns, 100'999'999_ns}) {
    EXPECT_FALSE(ans1(pulse_low(at, 27_ms)).applied) << at.count();
    EXPECT_FALSE(ans1(pulse_low(at, 27_ms)).depends_on_phase) << at.count();
    EXPECT_EQ(ans1(pulse_low(at, 27_ms)).rejected, std::vector<Nanos>{at});
    for (const Nanos w : {27_ms + 1_ns, 27'500'000_ns, 28_ms - 1_ns}) {
      EXPECT_TRUE(ans1(pulse_low(at, w)).depends_on_phase) << at.count() << " " << w.count();
      EXPECT_FALSE(ans1(pulse_low(at, w)).applied) << at.count() << " " << w.count();
    }
    EXPECT_EQ(ans1(pulse_low(at, 28_ms)).applied, at);
    EXPECT_EQ(ans1(pulse_low(at, 28_ms)).latest, at);
    EXPECT_FALSE(ans1(pulse_low(at, 28_ms)).depends_on_phase);
  }
  // Far below: a 2 ms glitch, a 15.9 ms pulse, 23 and 24 ms (aborted by the 8th released
  // sample) are noise; a line that stays applied qualifies.
  for (const Nanos w : {2_ms, 15'900_us, 16_ms, 23_ms, 24_ms, 25_ms})
    EXPECT_FALSE(ans1(pulse_low(100_ms, w)).applied) << w.count();
  EXPECT_EQ(ans1({{100_ms, Level::Low}}).applied, 100_ms);
}

// The glitch before the real application is dropped and the real one is timed; a board
// timing from the glitch would report a stop 65 ms too long (the check's fail of a correct
// board this rule prevents). A glitch shorter than the tick may go unseen: the same answer.
TEST(BrakeApplication, Ans1TimesTheApplicationAfterANoisyOne) {
  for (const Nanos width : {2_ms, 500_us}) {
    std::vector<Edge> line = pulse_low(60'300'000_ns, width);
    line.push_back({125_ms, Level::Low});
    const auto a = ans1(line);
    EXPECT_EQ(a.applied, 125_ms) << width.count();
    EXPECT_EQ(a.latest, 125_ms);
    EXPECT_FALSE(a.depends_on_phase);
    // Without a debounce the first transition is the application.
    EXPECT_EQ(brake_application(line, Level::High, Level::Low, 0_ms, 1'000_ms, BrakeDebounce::None).applied,
              60'300'000_ns);
  }
  std::vector<Edge> line = pulse_low(60_ms, 2_ms);
  line.push_back({125_ms, Level::Low});
  EXPECT_EQ(ans1(line).rejected, std::vector<Nanos>{60_ms});
  // A transition before `from` starts no cycle.
  EXPECT_EQ(brake_application(line, Level::High, Level::Low, 63_ms, 1'000_ms, BrakeDebounce::Ans1).applied,
            125_ms);
}

// Contact bounce within the first 16 ms is never sampled: the cycle is timed from the first
// transition. A bounce whose openings straddle the ticks: some phases see the cycle start at a
// later closing, under 16 ms on, so applied..latest spans them (the report window widens).
// Released during the sampling from 16 ms to 16 ms + r: with r <= 4 ms at most 4 samples are
// released on every phase (qualifies); r = 5 ms gives 5 on every phase: noise at 32 ms, the
// line applied then, so the debounce restarts at once, re-timed (digest A9); between them the
// phase decides.
TEST(BrakeApplication, Ans1SamplesFrom16MsAndRestartsWhenStillApplied) {
  std::vector<Edge> bounce{{100_ms, Level::Low}};
  for (int i = 0; i < 3; ++i) {
    bounce.push_back({100_ms + (2 * i + 1) * 1_ms, Level::High});
    bounce.push_back({100_ms + (2 * i + 2) * 1_ms, Level::Low});
  }
  EXPECT_EQ(ans1(bounce).applied, 100_ms);
  EXPECT_EQ(ans1(bounce).latest, 100_ms); // 1 ms openings: every tick sees the first closing
  std::vector<Edge> fast{{100_ms, Level::Low}, {100'300'000_ns, Level::High}, {100'600'000_ns, Level::Low}};
  EXPECT_EQ(ans1(fast).applied, 100_ms);
  EXPECT_EQ(ans1(fast).latest, 100'600'000_ns); // a tick in the opening sees the second closing
  const auto released = [](Nanos until) {
    return std::vector<Edge>{{100_ms, Level::Low}, {116_ms, Level::High}, {100_ms + until, Level::Low}};
  };
  EXPECT_EQ(ans1(released(20_ms)).applied, 100_ms);
  EXPECT_TRUE(ans1(released(20_ms + 1_ns)).depends_on_phase);
  EXPECT_TRUE(ans1(released(21_ms - 1_ns)).depends_on_phase);
  const auto restarted = ans1(released(21_ms));
  EXPECT_EQ(restarted.applied, 132_ms);
  EXPECT_EQ(restarted.rejected, std::vector<Nanos>{100_ms});
  // The 8th released sample (at 23 ms) aborts it at once; the line is released then, so the
  // next cycle starts at its next transition, 140 ms.
  std::vector<Edge> late{{100_ms, Level::Low}, {116_ms, Level::High}, {140_ms, Level::Low}};
  const auto a = ans1(late);
  EXPECT_EQ(a.applied, 140_ms);
  EXPECT_EQ(a.rejected, std::vector<Nanos>{100_ms});
}

// A cycle whose decision (t0 + 32 ms) falls after the capture's end qualified nothing the rig
// saw: with t0 up to 1 ms - 1 ns after the transition (ticks on the ns), only a capture to
// 33 ms - 1 ns after it sees every board decide.
TEST(BrakeApplication, Ans1DecisionAfterTheCaptureEndsQualifiesNothing) {
  const std::vector<Edge> line{{100_ms, Level::Low}};
  EXPECT_FALSE(ans1(line, 131'999'999_ns).applied);
  EXPECT_FALSE(ans1(line, 131'999'999_ns).depends_on_phase);
  EXPECT_TRUE(ans1(line, 132_ms).depends_on_phase);
  EXPECT_TRUE(ans1(line, 133_ms - 2_ns).depends_on_phase);
  EXPECT_EQ(ans1(line, 133_ms - 1_ns).applied, 100_ms); // the latest tick: 1 ms - 1 ns after it
  EXPECT_FALSE(brake_application(line, Level::High, Level::Low, 0_ms, 99_ms, BrakeDebounce::None).applied);
}

} // namespace
} // namespace hilrig::checks
