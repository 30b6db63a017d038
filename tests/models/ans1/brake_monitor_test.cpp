// Brake monitor (spec §4.10, manual L1027-L1056): start and stop timing, the 125 ms standstill
// window, the apply debounce (16 ms + 16 samples, 8/12 rules), faults and the never-faults
// variant. The engine is driven directly, one tick per millisecond.
#include <cmath>
#include <cstdint>
#include <functional>

#include <gtest/gtest.h>

#include "models/ans1/brake_monitor.hpp"

namespace hilrig::models::ans1 {
namespace {

using Phase = BrakeMonitor::Phase;

// Runs ticks at t = from..to ms (inclusive) with the brake input and position given per ms.
struct BrakeRig {
  BrakeMonitor brake;
  std::function<bool(std::int64_t)> released = [](std::int64_t) { return true; };
  std::function<std::int64_t(std::int64_t)> pos = [](std::int64_t) { return std::int64_t{0}; };
  std::int64_t now_ms = 0;

  explicit BrakeRig(const BrakeSetup& setup, bool never_faults = false) : brake(never_faults) {
    brake.configure(setup);
  }
  void run_to(std::int64_t to_ms) {
    for (; now_ms <= to_ms; ++now_ms) {
      brake.tick(milliseconds(now_ms), released(now_ms), pos(now_ms),
                 static_cast<std::uint16_t>(now_ms % 360));
    }
  }
};

BrakeSetup setup_with(std::uint8_t csc, std::uint16_t start_limit, std::uint16_t stop_limit) {
  BrakeSetup s;
  s.input = 3;
  s.complete_stop_count = csc;
  s.start_time_limit_ms = start_limit;
  s.start_overrun_output = 9;
  s.stop_time_limit_ms = stop_limit;
  s.stop_overrun_output = 10;
  return s;
}

// Applied at 100 ms; the press runs at 41 counts/ms until 250 ms (150 ms after application),
// then stands still.
void constant_speed_then_stop(BrakeRig& rig) {
  rig.released = [](std::int64_t t) { return t < 100; };
  rig.pos = [](std::int64_t t) { return 41 * std::min<std::int64_t>(t, 250); };
}

TEST(BrakeMonitor, W17StopTimeIsStopTimerMinus125ms) {
  // W-17 (L1052): the stop timer reads 275 ms when standstill is detected -> 150 ms reported.
  // By hand: with CSC 10 the window [now-125, now] holds < 10 counts only once it lies wholly
  // after the stop at 150 ms, i.e. at now = 150 + 125 = 275 ms after application.
  BrakeRig rig(setup_with(10, 0, 0));
  constant_speed_then_stop(rig);
  rig.run_to(100 + 274);
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
  rig.run_to(100 + 275);
  EXPECT_EQ(rig.brake.phase(), Phase::Idle);
  EXPECT_EQ(rig.brake.status().completed_stops, 1U);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 150);
}

TEST(BrakeMonitor, AppliedPositionIsPublishedOnlyAtStandstill) {
  // L1038: the applied position (GMP at application) appears in DA19 w5 only when the stop
  // time is published. The rig's GMP is t mod 360, so the application at 100 ms reads 100.
  BrakeRig rig(setup_with(10, 0, 0));
  constant_speed_then_stop(rig);
  rig.run_to(300);
  EXPECT_EQ(rig.brake.status().applied_position, 0);
  rig.run_to(400);
  EXPECT_EQ(rig.brake.status().applied_position, 100);
}

TEST(BrakeMonitor, LinearDecelerationMatchesClosedForm) {
  // Spec §4.10 closed form: reported = T_stop - tau, tau = sqrt(2*CSC/decel). Here decel is
  // 0.1 counts/ms^2 from 20 counts/ms, so T_stop = 200 ms; CSC 20 gives tau = 20 ms and
  // reported ~180 ms. With 1 ms ticks and the strict "< CSC": at now-125 = 180 the window still
  // holds 0.05*20^2 = 20 counts (not < 20); at 181 it holds 18.05 -> detected, reports 181.
  BrakeRig rig(setup_with(20, 0, 0));
  rig.released = [](std::int64_t t) { return t < 0 + 1; }; // applied at 1 ms
  rig.pos = [](std::int64_t t) {
    const double ms = static_cast<double>(std::min<std::int64_t>(t - 1, 200));
    return static_cast<std::int64_t>(std::llround(20.0 * ms - 0.05 * ms * ms));
  };
  rig.run_to(600);
  ASSERT_EQ(rig.brake.status().completed_stops, 1U);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 181);
}

TEST(BrakeMonitor, PressAlreadyStillReportsZeroAfterTheFull125msWindow) {
  // The window must lie wholly after the application [MODEL A10]: a still press is detected
  // 125 ms after application, stop time 0.
  BrakeRig rig(setup_with(5, 0, 0));
  rig.released = [](std::int64_t t) { return t < 10; };
  rig.run_to(10 + 124);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
  rig.run_to(10 + 125);
  EXPECT_EQ(rig.brake.status().completed_stops, 1U);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 0);
}

TEST(BrakeMonitor, CompleteStopCountZeroNeverDetectsStandstill) {
  // A10: "< 0 counts" can never hold, so the cycle never ends.
  BrakeRig rig(setup_with(0, 0, 0));
  rig.released = [](std::int64_t t) { return t < 10; };
  rig.run_to(5000);
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
}

TEST(BrakeMonitor, MotionWindowUsesTheUnwrappedPosition) {
  // CSC is on a 4096/turn base; a press creeping 1 count/ms across a turn boundary is still
  // moving (125 counts per window), whatever the turn number.
  BrakeRig rig(setup_with(100, 0, 0));
  rig.released = [](std::int64_t t) { return t < 10; };
  rig.pos = [](std::int64_t t) { return 4000 + t; };
  rig.run_to(2000);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
}

TEST(BrakeMonitor, ShortApplyPulseIsRejectedAsNoise) {
  // Applied for 10 ms only: all 16 samples at 16..31 ms read "released"; the 8th (at 23 ms)
  // aborts (L1039). No stop is measured.
  BrakeRig rig(setup_with(10, 0, 0));
  rig.released = [](std::int64_t t) { return t < 100 || t >= 110; };
  rig.run_to(100 + 22);
  EXPECT_EQ(rig.brake.phase(), Phase::Debouncing);
  rig.run_to(100 + 23);
  EXPECT_EQ(rig.brake.phase(), Phase::Idle);
  EXPECT_EQ(rig.brake.status().noise_rejections, 1U);
  rig.run_to(1000);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
}

TEST(BrakeMonitor, BounceBeforeTheSampleWindowIsIgnored) {
  // Contact bounce in the first 16 ms is not sampled: released at 2..9 ms, then applied.
  BrakeRig rig(setup_with(10, 0, 0));
  rig.released = [](std::int64_t t) { return t < 100 || (t >= 102 && t < 110); };
  rig.run_to(100 + 32);
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
  rig.run_to(1000);
  EXPECT_EQ(rig.brake.status().completed_stops, 1U);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 0); // press already still: 125 - 125
}

TEST(BrakeMonitor, TwelveOfSixteenAppliedSamplesQualify) {
  // 4 "released" samples (16, 20, 24, 28 ms) leave 12 "applied": qualified at 32 ms (L1040).
  BrakeRig rig(setup_with(10, 0, 0));
  rig.released = [](std::int64_t t) {
    const std::int64_t d = t - 100;
    return d < 0 || (d >= 16 && d <= 28 && d % 4 == 0);
  };
  rig.run_to(100 + 32);
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
  EXPECT_EQ(rig.brake.status().noise_rejections, 0U);
}

TEST(BrakeMonitor, ElevenAppliedSamplesAbortAndRestartWhileStillApplied) {
  // 5 "released" samples (16, 19, 22, 25, 28 ms) leave 11 "applied" < 12: noise at 32 ms. The
  // input is applied then, so the debounce restarts at once with t0 = 132 ms [MODEL A9] and
  // qualifies 32 ms later. A still press then reports 125 ms after the restart: stop time 0.
  BrakeRig rig(setup_with(10, 0, 0));
  rig.released = [](std::int64_t t) {
    const std::int64_t d = t - 100;
    return d < 0 || (d >= 16 && d <= 28 && (d - 16) % 3 == 0);
  };
  rig.run_to(100 + 32);
  EXPECT_EQ(rig.brake.phase(), Phase::Debouncing);
  EXPECT_EQ(rig.brake.status().noise_rejections, 1U);
  rig.run_to(132 + 31);
  EXPECT_EQ(rig.brake.phase(), Phase::Debouncing);
  rig.run_to(132 + 32);
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
  rig.run_to(132 + 124);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
  rig.run_to(132 + 125);
  EXPECT_EQ(rig.brake.status().completed_stops, 1U);
}

// Drives ticks on the whole ms and the debounce samples between them in time order, as
// Monitors::scan does, with the input level at each instant.
void run_with_samples(BrakeMonitor& brake, Nanos& next_tick, Nanos to,
                      const std::function<bool(Nanos)>& released) {
  while (true) {
    const Nanos sample = brake.next_sample();
    if (sample < next_tick && sample <= to) {
      brake.sample(sample, released(sample), 0);
    } else if (next_tick <= to) {
      brake.tick(next_tick, released(next_tick), 0, 0);
      next_tick += BrakeMonitor::kTick;
    } else {
      return;
    }
  }
}

TEST(BrakeMonitor, SampleStartOffTheWholeMillisecondSamplesBetweenTicks) {
  // L1039-L1040: sampling starts sample_start after the edge (taken on the 100 ms tick), once a
  // ms; the 12th sample is at 100 + 16.3 + 11 = 127.3 ms. Applied until just after it: 12
  // applied samples (116.3 .. 127.3 ms) qualify at the decision, 1 ms after the 16th (132.3 ms).
  // Released exactly at 127.3 ms: 11 applied, noise at 132.3 ms, and the monitor waits idle.
  for (const std::int64_t extra_ns : {1, 0}) {
    SCOPED_TRACE(extra_ns);
    BrakeMonitor brake(false, microseconds(16'300));
    brake.configure(setup_with(10, 0, 0));
    const Nanos end = microseconds(127'300) + Nanos{extra_ns};
    const auto released = [end](Nanos t) { return t < milliseconds(100) || t >= end; };
    Nanos next_tick{0};
    run_with_samples(brake, next_tick, microseconds(132'300) - Nanos{1}, released);
    EXPECT_EQ(brake.phase(), Phase::Debouncing);
    EXPECT_EQ(brake.next_sample(), microseconds(132'300));
    run_with_samples(brake, next_tick, microseconds(132'300), released);
    EXPECT_EQ(brake.phase(), extra_ns > 0 ? Phase::Stopping : Phase::Idle);
    EXPECT_EQ(brake.status().noise_rejections, extra_ns > 0 ? 0U : 1U);
  }
}

TEST(BrakeMonitor, InputIsIgnoredOnceQualified) {
  // Released again at 200 ms (after qualification): the stop cycle still completes (L1041).
  BrakeRig rig(setup_with(10, 0, 0));
  constant_speed_then_stop(rig);
  rig.released = [](std::int64_t t) { return t < 100 || t >= 200; };
  rig.run_to(500);
  EXPECT_EQ(rig.brake.status().completed_stops, 1U);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 150);
}

TEST(BrakeMonitor, StartTimeIsReleaseToMotionBeyondTwiceCsc) {
  // Released at 50 ms; the press moves 1 count/ms from 90 ms. CSC 10 needs > 20 counts:
  // pos - pos(t1) = t - 90 > 20 first at t = 111 -> start time 111 - 50 = 61 ms (L1056).
  BrakeRig rig(setup_with(10, 0, 0));
  rig.released = [](std::int64_t t) { return t >= 50; };
  rig.pos = [](std::int64_t t) { return t < 90 ? 0 : t - 90; };
  rig.run_to(110);
  EXPECT_EQ(rig.brake.phase(), Phase::Starting);
  rig.run_to(111);
  EXPECT_EQ(rig.brake.phase(), Phase::Idle);
  EXPECT_EQ(rig.brake.status().start_time_ms, 61);
  EXPECT_EQ(rig.brake.status().released_position, 50);
}

TEST(BrakeMonitor, StartTimeOver32767IsReportedAs32768) {
  // L2616 [A8]: a start longer than 32,767 ms reads 32,768.
  BrakeRig rig(setup_with(1, 0, 0));
  rig.released = [](std::int64_t t) { return t >= 1; };
  rig.pos = [](std::int64_t t) { return t < 40000 ? 0 : 10; };
  rig.run_to(40001);
  EXPECT_EQ(rig.brake.status().completed_starts, 1U);
  EXPECT_EQ(rig.brake.status().start_time_ms, 32768);
}

TEST(BrakeMonitor, StartOverLimitFaultsAndAStartWithinLimitClearsIt) {
  BrakeRig rig(setup_with(10, 60, 0));
  // First start 61 ms > 60 -> fault. Then applied at 200 (still press), released at 600 and
  // moving at once, 21 counts after 21 ms -> 21 ms within limit -> fault cleared.
  rig.released = [](std::int64_t t) { return (t >= 50 && t < 200) || t >= 600; };
  rig.pos = [](std::int64_t t) {
    if (t < 90) return std::int64_t{0};
    if (t < 120) return t - 90;
    if (t < 600) return std::int64_t{30};
    return 30 + (t - 600);
  };
  rig.run_to(150);
  EXPECT_EQ(rig.brake.status().start_time_ms, 61);
  EXPECT_TRUE(rig.brake.start_fault());
  rig.run_to(700);
  EXPECT_EQ(rig.brake.status().start_time_ms, 21);
  EXPECT_FALSE(rig.brake.start_fault());
}

TEST(BrakeMonitor, StopOverLimitFaultsUntilClearErrors) {
  BrakeRig rig(setup_with(10, 0, 149)); // 150 ms measured > 149 ms limit
  constant_speed_then_stop(rig);
  rig.run_to(500);
  EXPECT_TRUE(rig.brake.stop_fault());
  rig.brake.clear_errors();
  EXPECT_FALSE(rig.brake.stop_fault());
}

TEST(BrakeMonitor, StopAtTheLimitIsNotAFault) {
  BrakeRig rig(setup_with(10, 0, 150)); // 150 ms measured, limit 150: not over
  constant_speed_then_stop(rig);
  rig.run_to(500);
  EXPECT_EQ(rig.brake.status().stop_time_ms, 150);
  EXPECT_FALSE(rig.brake.stop_fault());
}

TEST(BrakeMonitor, NeverFaultsVariantMeasuresButNeverFaults) {
  BrakeRig good(setup_with(10, 0, 100));
  BrakeRig bad(setup_with(10, 0, 100), /*never_faults=*/true);
  constant_speed_then_stop(good);
  constant_speed_then_stop(bad);
  good.run_to(500);
  bad.run_to(500);
  EXPECT_EQ(bad.brake.status().stop_time_ms, good.brake.status().stop_time_ms);
  EXPECT_TRUE(good.brake.stop_fault());
  EXPECT_FALSE(bad.brake.stop_fault());
}

TEST(BrakeMonitor, DisabledMonitorMeasuresNothing) {
  BrakeSetup off = setup_with(10, 0, 100);
  off.input = 0;
  BrakeRig rig(off);
  constant_speed_then_stop(rig);
  rig.run_to(500);
  EXPECT_EQ(rig.brake.status().completed_stops, 0U);
  EXPECT_EQ(rig.brake.phase(), Phase::Idle);
}

// A press released at 50 ms that never moves. ans1 manual (seeds/000_08a2edf5547d4d1e.txt:1056):
// the start time runs from release to motion > 2*CSC and the Start Time Limit turns the fault
// output off "if the starting time is exceeded" -- exceeded by the clock, motion or not.
TEST(BrakeMonitor, ReleasedPressThatNeverMovesTripsTheStartFaultWhenTheLimitExpires) {
  for (const int limit : {1, 2, 59, 60, 61, 1000, 32766, 32767}) {
    BrakeRig rig(setup_with(10, static_cast<std::uint16_t>(limit), 0));
    rig.released = [](std::int64_t t) { return t >= 50; };
    // Elapsed = limit ms is at the limit: not exceeded (one inclusive rule, like finish_start).
    rig.run_to(50 + limit);
    EXPECT_FALSE(rig.brake.start_fault()) << "limit " << limit;
    rig.run_to(50 + limit + 1);
    EXPECT_TRUE(rig.brake.start_fault()) << "limit " << limit;
    EXPECT_EQ(rig.brake.phase(), Phase::Starting) << "limit " << limit; // the timer still runs
    EXPECT_EQ(rig.brake.status().completed_starts, 0U);
  }
}

TEST(BrakeMonitor, StartTimeOverflowIsRecordedWhileThePressStillHasNotMoved) {
  // seeds/000_08a2edf5547d4d1e.txt:2616 (DA19 w4): "If the time exceeds 32,767 milliseconds, a
  // value of 32,768 is recorded" -- recorded once exceeded, without waiting for motion.
  BrakeRig rig(setup_with(10, 0, 0)); // limit 0: no fault [MODEL A44], the report still overflows
  rig.released = [](std::int64_t t) { return t >= 50; };
  rig.run_to(50 + 32767);
  EXPECT_EQ(rig.brake.status().start_time_ms, 0);
  rig.run_to(50 + 32768);
  EXPECT_EQ(rig.brake.status().start_time_ms, 32768);
  EXPECT_FALSE(rig.brake.start_fault());
}

TEST(BrakeMonitor, StartFaultTrippedByTheClockStaysWhenThePressFinallyMovesLate) {
  // Released at 50, limit 60, motion > 2*CSC only at 200 (start time 150 > 60): tripped at
  // 111 ms by the clock and still tripped when the late start is measured (L1056).
  BrakeRig rig(setup_with(10, 60, 0));
  rig.released = [](std::int64_t t) { return t >= 50; };
  rig.pos = [](std::int64_t t) { return t < 200 ? 0 : 100; };
  rig.run_to(111);
  EXPECT_TRUE(rig.brake.start_fault());
  rig.run_to(300);
  EXPECT_EQ(rig.brake.status().start_time_ms, 150);
  EXPECT_TRUE(rig.brake.start_fault());
}

TEST(BrakeMonitor, ClearErrorsHoldsWhileTheOverrunningStartIsStillTimed) {
  // Cleared at 200 while the press still has not moved: the trip is once per cycle [MODEL A44,
  // clearing not stated], so the fault stays cleared until the cycle is judged at motion.
  BrakeRig rig(setup_with(10, 60, 0));
  rig.released = [](std::int64_t t) { return t >= 50; };
  rig.pos = [](std::int64_t t) { return t < 400 ? 0 : 100; };
  rig.run_to(200);
  ASSERT_TRUE(rig.brake.start_fault());
  rig.brake.clear_errors();
  rig.run_to(399);
  EXPECT_FALSE(rig.brake.start_fault());
  rig.run_to(400);
  EXPECT_TRUE(rig.brake.start_fault()); // 350 ms > 60 ms, judged at motion
}

TEST(BrakeMonitor, NeverFaultsVariantDoesNotTripAStartThatNeverMoves) {
  BrakeRig rig(setup_with(10, 60, 0), /*never_faults=*/true);
  rig.released = [](std::int64_t t) { return t >= 50; };
  rig.run_to(1000);
  EXPECT_FALSE(rig.brake.start_fault());
}

// Brake applied at 100 ms while the press keeps turning at 41 counts/ms (a failed brake).
// seeds/000_08a2edf5547d4d1e.txt:1042 and :1052: standstill is < CSC counts in 125 ms and 125 ms
// is subtracted from the reported stop time, so standstill detected at tick t reports
// t - 100 - 125. Still turning at tick 100 + limit + 125 means the stop time will be at least
// limit + 1: the overrun is certain there and trips -- not one tick earlier.
TEST(BrakeMonitor, BrakeAppliedWhileThePressKeepsTurningTripsTheStopFaultWhenTheLimitExpires) {
  for (const int limit : {1, 2, 149, 150, 151, 2000, 32767}) {
    BrakeRig rig(setup_with(10, 0, static_cast<std::uint16_t>(limit)));
    rig.released = [](std::int64_t t) { return t < 100; };
    rig.pos = [](std::int64_t t) { return 41 * t; };
    rig.run_to(100 + limit + 124);
    EXPECT_FALSE(rig.brake.stop_fault()) << "limit " << limit;
    rig.run_to(100 + limit + 125);
    EXPECT_TRUE(rig.brake.stop_fault()) << "limit " << limit;
    EXPECT_EQ(rig.brake.phase(), Phase::Stopping) << "limit " << limit; // still timing the stop
    EXPECT_EQ(rig.brake.status().completed_stops, 0U);
  }
}

TEST(BrakeMonitor, StopFaultByTheClockAgreesWithTheMeasuredStopAroundTheLimit) {
  // The press stops 150 ms after application (measured 150 ms, see W17 above). Sweep the limit
  // across 150: over-limit iff 150 > limit, and the trip never comes before 100 + limit + 125.
  for (int limit = 140; limit <= 160; ++limit) {
    BrakeRig rig(setup_with(10, 0, static_cast<std::uint16_t>(limit)));
    constant_speed_then_stop(rig);
    rig.run_to(100 + limit + 124);
    EXPECT_FALSE(rig.brake.stop_fault()) << "limit " << limit;
    rig.run_to(1000);
    EXPECT_EQ(rig.brake.status().stop_time_ms, 150);
    EXPECT_EQ(rig.brake.stop_fault(), 150 > limit) << "limit " << limit;
  }
}

TEST(BrakeMonitor, ClearErrorsHoldsWhileTheFailedBrakeIsStillTimed) {
  // The same failed brake, stop limit 200: tripped at 100 + 200 + 125 = 425 ms, the cycle is
  // still running then; Clear Errors clears it and the running cycle does not trip it again.
  BrakeRig rig(setup_with(10, 0, 200));
  rig.released = [](std::int64_t t) { return t < 100; };
  rig.pos = [](std::int64_t t) { return 41 * t; };
  rig.run_to(425);
  EXPECT_TRUE(rig.brake.stop_fault());
  rig.brake.clear_errors();
  rig.run_to(5000);
  EXPECT_FALSE(rig.brake.stop_fault());
  EXPECT_EQ(rig.brake.phase(), Phase::Stopping);
}

// The level the brake input has when CB8 takes effect (L1054-L1056, L2614): a release after it
// is an inactive-to-active transition the first tick must see, whether it comes before that
// tick or not; a level already active then is no transition.
TEST(BrakeMonitor, ReleaseBetweenTheSetupAndTheFirstTickIsTimed) {
  for (const bool released_when_programmed : {false, true}) {
    BrakeMonitor brake;
    brake.configure(setup_with(10, 0, 0), released_when_programmed);
    brake.tick(milliseconds(1), true, 0, 42);
    EXPECT_EQ(brake.phase(), released_when_programmed ? Phase::Idle : Phase::Starting);
    EXPECT_EQ(brake.status().released_position, released_when_programmed ? 0 : 42);
  }
}

TEST(BrakeMonitor, WithoutALevelAtTheSetupTheFirstTickTakesIt) {
  // Programmed before the device has read its inputs (power-up): an input already active at the
  // first tick is the press's state, not a release.
  BrakeMonitor active;
  active.configure(setup_with(10, 0, 0));
  active.tick(milliseconds(1), true, 0, 42);
  EXPECT_EQ(active.phase(), Phase::Idle);
  EXPECT_EQ(active.status().released_position, 0);
  // Inactive at the first tick: the next active tick is a release.
  BrakeMonitor inactive;
  inactive.configure(setup_with(10, 0, 0));
  inactive.tick(milliseconds(1), false, 0, 42);
  EXPECT_EQ(inactive.phase(), Phase::Idle);
  inactive.tick(milliseconds(2), true, 0, 43);
  EXPECT_EQ(inactive.phase(), Phase::Starting);
  EXPECT_EQ(inactive.status().released_position, 43);
}

TEST(BrakeMonitor, ANewSetupOnTheSameInputKeepsTheLevelItsLastTickSaw) {
  // Tick at 1 ms: applied. The input is released at 1.3 ms and new limits arrive at 1.5 ms: the
  // ticks go on sampling input 3, so the 2 ms tick finds the release. A new input starts from
  // its own level when programmed.
  BrakeMonitor brake;
  brake.configure(setup_with(10, 0, 0), false);
  brake.tick(milliseconds(1), false, 0, 10);
  brake.configure(setup_with(10, 300, 50), true);
  brake.tick(milliseconds(2), true, 0, 20);
  EXPECT_EQ(brake.phase(), Phase::Starting);
  EXPECT_EQ(brake.status().released_position, 20);

  BrakeSetup other = setup_with(10, 300, 50);
  other.input = 4;
  brake.configure(other, true);
  brake.tick(milliseconds(3), true, 0, 30);
  EXPECT_EQ(brake.phase(), Phase::Idle);
  EXPECT_EQ(brake.status().released_position, 20);
}

} // namespace
} // namespace hilrig::models::ans1
