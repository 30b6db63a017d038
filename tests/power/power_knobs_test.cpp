// Detection power of the pulse-width, frame-start and shaft-move checks, on the knobs the
// 7361, ANS1 and SMD23E models gained for them: each threshold `hilrig power` bisects must be
// where the manual's arithmetic puts it, and a sweep of the knob across it must pass up to the
// limit and fail beyond (the bisection's own probe, rig/power/power.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/power/knobs.hpp"
#include "rig/power/power.hpp"

namespace hilrig::power {
namespace {

campaign::Campaign load(const std::string& relative) {
  return campaign::load_campaign(std::string(HILRIG_SOURCE_DIR) + "/" + relative);
}

const PowerRow& row_of(const PowerResult& r, const std::string& check, const std::string& direction) {
  for (const PowerRow& row : r.rows)
    if (row.check == check && row.direction == direction) return row;
  throw std::runtime_error("no row " + check + " " + direction);
}

// Sweeps a duration knob over [from, to] ns in steps of `step` ns: every value below `first_fail`
// passes, every value from it fails.
void sweep_ns(const campaign::Campaign& c, const std::string& check, const std::string& knob,
              std::int64_t from, std::int64_t to, std::int64_t step, std::int64_t first_fail, int sign) {
  for (std::int64_t v = from; sign > 0 ? v <= to : v >= to; v += sign * step) {
    SCOPED_TRACE(check + ": " + knob + " = " + std::to_string(v) + " ns");
    const bool beyond = sign > 0 ? v >= first_fail : v <= first_fail;
    EXPECT_EQ(probe_param(c, check, knob, Nanos{v}, c.seed), beyond ? Probe::Fail : Probe::Pass);
  }
}

// ssi7361 manual (seeds/004_2d8564fc60a2b9d4.txt:1123): the clock is 125 kHz, T = 8 us; 50 % duty
// (docs/spec/ssi7361.md §2.1 [MODEL]): each low half lasts T/2 (in whole ns, the model halves T by
// truncation). ssi7361_frame_timing judges the low halves at exactly 4 us (min = max). With the
// clock period T + e: e = +1 ns gives halves of floor(8001 / 2) = 4000 ns (pass), e = +2 ns
// 4001 ns (fail); e = -1 ns 3999 ns (fail). The high pulses: within a frame T - floor(T/2), and
// from R25 to the next F1 TINT - (24 T + T/2) (L1090-L1091: TINT 500 us), 304 us at e = 0, under
// the check's max of 312 us (304 us + the frame start's +- T/2 on both frames). Downward the
// in-frame high fails first: e = -1 ns gives 7999 - 3999 = 4000 ns (pass), e = -2 ns 7998 -
// 3999 = 3999 ns, under min_us 4; the gap reaches 312 us only at e = -327 ns. A longer clock
// only shortens the gap and lengthens the in-frame high (which 312 us bounds loosely), so the
// clock period never fails that check upward within the knob's range.
TEST(PowerSsi7361, ClockHalvesFailOneOrTwoNanosecondsOffTheManualsPeriod) {
  const campaign::Campaign c = load("campaigns/ssi7361/ssi7361_frame_timing.toml");
  PowerOptions options;
  options.checks = {"clock_low_half_period", "clock_high"};
  const PowerResult r = measure_power(c, options);
  ASSERT_EQ(r.rows.size(), 4u);

  const PowerRow& low_up = row_of(r, "clock_low_half_period", "up");
  EXPECT_EQ(low_up.knob, "clock_period_error");
  EXPECT_TRUE(low_up.two_sided);
  ASSERT_TRUE(low_up.threshold && low_up.measured && low_up.limit) << low_up.reason;
  EXPECT_NEAR(*low_up.threshold, 0.002, 1e-12);
  EXPECT_NEAR(*low_up.last_pass, 0.001, 1e-12);
  EXPECT_EQ(low_up.measurement, "clock_low_half_period.longest");
  EXPECT_DOUBLE_EQ(*low_up.measured, 4.001);
  EXPECT_DOUBLE_EQ(*low_up.limit, 4.0);

  const PowerRow& low_down = row_of(r, "clock_low_half_period", "down");
  ASSERT_TRUE(low_down.threshold && low_down.measured) << low_down.reason;
  EXPECT_NEAR(*low_down.threshold, -0.001, 1e-12);
  EXPECT_EQ(low_down.measurement, "clock_low_half_period.shortest");
  EXPECT_DOUBLE_EQ(*low_down.measured, 3.999);

  const PowerRow& high_down = row_of(r, "clock_high", "down");
  ASSERT_TRUE(high_down.threshold && high_down.measured && high_down.limit) << high_down.reason;
  EXPECT_NEAR(*high_down.threshold, -0.002, 1e-12);
  EXPECT_EQ(high_down.measurement, "clock_high.shortest");
  EXPECT_DOUBLE_EQ(*high_down.measured, 3.999);
  EXPECT_DOUBLE_EQ(*high_down.limit, 4.0);

  const PowerRow& high_up = row_of(r, "clock_high", "up");
  EXPECT_FALSE(high_up.threshold.has_value());
  EXPECT_EQ(high_up.reason.rfind("never fails within knob range clock_period_error", 0), 0u)
      << high_up.reason;

  sweep_ns(c, "clock_low_half_period", "clock_period_error", 0, 4, 1, 2, +1);
  sweep_ns(c, "clock_low_half_period", "clock_period_error", 1, -3, 1, -1, -1);
}

// ssi7361 manual (seeds/004_2d8564fc60a2b9d4.txt:1090, :1096): a frame starts every TINT =
// 500 us at 125 kHz. ssi7361_frame_timing expects F1 at 100 us + k * 500 us, k = 0..19, and
// takes each frame's first falling clock edge within +- T/2 = 4 us (docs/spec/ssi7361.md §2.1,
// A7). With TINT + e the 20th frame starts 19 e off: 19 * 210 ns = 3.99 us passes, 19 * 211 ns =
// 4.009 us fails, late (up) and early (down) alike.
TEST(PowerSsi7361, FrameStartFailsWhenTheTwentiethFrameDriftsPastHalfAClock) {
  const campaign::Campaign c = load("campaigns/ssi7361/ssi7361_frame_timing.toml");
  PowerOptions options;
  options.checks = {"frame_start"};
  const PowerResult r = measure_power(c, options);
  ASSERT_EQ(r.rows.size(), 2u);
  for (const char* side : {"up", "down"}) {
    const double sign = std::string(side) == "up" ? 1.0 : -1.0;
    const PowerRow& row = row_of(r, "frame_start", side);
    EXPECT_EQ(row.knob, "frame_period_error");
    ASSERT_TRUE(row.threshold && row.measured && row.limit && row.margin_pct) << row.reason;
    EXPECT_NEAR(*row.threshold, sign * 0.211, 1e-12);
    EXPECT_NEAR(*row.last_pass, sign * 0.210, 1e-12);
    EXPECT_DOUBLE_EQ(*row.measured, sign * 4.009);
    EXPECT_DOUBLE_EQ(*row.limit, sign * 4.0);
    EXPECT_LE(*row.margin_pct, 1.0);
  }
  sweep_ns(c, "frame_start", "frame_period_error", 208, 214, 1, 211, +1);
  sweep_ns(c, "frame_start", "frame_period_error", -208, -214, 1, -211, -1);
}

// ans1 manual (seeds/000_08a2edf5547d4d1e.txt:1961-1962): a Time-or-Position output turns off
// when its timer (CB5 word 4, ms) expires, a Time-Only output when its timer expires. The
// model starts the timer at the scan that turns the output on and turns it off at the first
// scan (every 10 us, L572 docs/spec/ans1.md L187) at least timer + e later; both edges carry the
// same output delay. So the on time is ceil((timer + e) / 10 us) * 10 us. ans1_timed judges the
// 5 ms TP output within 4..6 ms and the 20 ms TO output within 19..21 ms (timer +- one 1 ms
// tick, L640): the on time passes up to e = +1 ms exactly (6 / 21 ms, inclusive) and fails at
// 1 ms + 1 ns (6.01 / 21.01 ms); downward it stays 4 / 19 ms until e = -1.01 ms (3.99 / 18.99 ms).
// (The bisection itself is run on the 7361 and SMD23E campaigns above and below; here the sweep
// probes the same thresholds, which is all a threshold means, at a tenth of the cost.)
TEST(PowerAns1Timed, TimerErrorPassesAtOneMillisecondAndFailsOneNanosecondBeyond) {
  const campaign::Campaign c = load("campaigns/ans1/ans1_timed.toml");
  EXPECT_EQ(knob_for("ans1", "pulse_width").param, "timer_error");
  EXPECT_EQ(knob_for("ans1", "pulse_width").direction, KnobDirection::Both);
  for (const char* check : {"tp_timer", "to_timer"}) {
    sweep_ns(c, check, "timer_error", 999'999, 1'000'002, 1, 1'000'001, +1);
    sweep_ns(c, check, "timer_error", -1'009'999, -1'010'001, 1, -1'010'000, -1);
  }
}

// smd23e manual (seeds/003_7a93cebfafae55cd.txt:921-927, docs/spec/smd23e.md §3.2): the trapezoid of
// smd23e_profile (N = 4000 steps, v_s = 1000, v_p = 10000 steps/s, A = D = 100 steps/ms/s) cruises at 10000
// steps/s, one step every 100 us; the check's peak (1 / the shortest step interval) must lie in 10000 +- 1 %.
// With the indexer's time base off by e, every interval is 100 (1 + e) us, rounded to whole ns in the step
// times, so one interval may be 1 ns shorter: the peak falls under 9900 when 100000 (1 + e) - 1 ns > 1e9 /
// 9900 ns, so from e in (0.0101010, 0.0101111]; it rises over 10100 when 100000 (1 + e) - 1 < 1e9 / 10100, so
// from e in [-0.0099010, -0.0098910). The ±(2 ms + 1 %) duration window is wider than the peak's ±1 %, so the
// peak fails first. (1e-6 of the knob's unit is the resolution.)
TEST(PowerSmd23e, StepClockErrorFailsThePeakJustBeyondOnePercent) {
  const campaign::Campaign c = load("campaigns/smd23e/smd23e_profile.toml");
  PowerOptions options;
  options.checks = {"trapezoid"};
  const PowerResult r = measure_power(c, options);
  ASSERT_EQ(r.rows.size(), 2u);
  const PowerRow& up = row_of(r, "trapezoid", "up");
  EXPECT_EQ(up.knob, "step_clock_error");
  ASSERT_TRUE(up.threshold && up.measured && up.limit && up.margin_pct) << up.reason;
  EXPECT_GE(*up.threshold, 1.0 / 0.99 - 1.0);
  EXPECT_LE(*up.threshold, (1e9 / 9900.0 + 1.0) / 100000.0 - 1.0 + 1e-6);
  EXPECT_EQ(up.measurement, "trapezoid.peak_speed");
  EXPECT_DOUBLE_EQ(*up.limit, 9900.0);
  EXPECT_LE(*up.margin_pct, 0.01);
  const PowerRow& down = row_of(r, "trapezoid", "down");
  ASSERT_TRUE(down.threshold && down.measured && down.limit && down.margin_pct) << down.reason;
  EXPECT_GE(*down.threshold, 1.0 / 1.01 - 1.0 - 1e-6);
  EXPECT_LE(*down.threshold, (1e9 / 10100.0 + 1.0) / 100000.0 - 1.0 + 1e-6);
  EXPECT_DOUBLE_EQ(*down.limit, 10100.0);
  EXPECT_LE(*down.margin_pct, 0.01);
  // Across it: 1 % slower passes (peak 9901 steps/s), 1.02 % fails (9899 steps/s); 0.98 %
  // faster passes, 1 % faster fails (10101 steps/s).
  EXPECT_EQ(probe_param(c, "trapezoid", "step_clock_error", 0.0100, c.seed), Probe::Pass);
  EXPECT_EQ(probe_param(c, "trapezoid", "step_clock_error", 0.0102, c.seed), Probe::Fail);
  EXPECT_EQ(probe_param(c, "trapezoid", "step_clock_error", -0.0098, c.seed), Probe::Pass);
  EXPECT_EQ(probe_param(c, "trapezoid", "step_clock_error", -0.0100, c.seed), Probe::Fail);
}

// output_off_skew: an output driver that turns off slower (or on slower) than on, so every ON
// pulse reaches the pin longer (shorter) by the skew (core/skewed_output.hpp; unit and
// property tests in tests/core/skewed_output_test.cpp). Each manual states one throughput for
// both edges of an output, so the on width at the pin is the board's commanded width:
//
// ans1_counters batch1_done_width: the batch output is on from one GMP 180 to the next, one turn
// at 600 rpm = 100 ms exactly (ans1 manual seeds/000_08a2edf5547d4d1e.txt:2211-2214, batch
// overflow output; both edges carry the same scan phase and output delay, L572, since 100 ms is
// 10000 whole 10 us scans), judged within 100 ms +- 10 us: the skew passes at +-10 us exactly
// (inclusive) and fails 1 ns beyond.
TEST(PowerPulseKnobs, Ans1BatchOutputFailsOneNanosecondBeyondTenMicrosecondsOfSkew) {
  const campaign::Campaign c = load("campaigns/ans1/ans1_counters.toml");
  sweep_ns(c, "batch1_done_width", "output_off_skew", 9'998, 10'002, 1, 10'001, +1);
  sweep_ns(c, "batch1_done_width", "output_off_skew", -9'998, -10'002, 1, -10'001, -1);
}

// amci4501_pass cycle_output_start_to_latch: the Cycle Output is on from Start to Latch (4501
// manual seeds/001_8422c5eec3a3e376.txt:7), and each edge may lag its input by up to the 125 us
// throughput on its own (L281; examples §0.6, each edge within [t, t + 125 us]), so the check
// allows Latch - Start +- 125 us: 2,000 - 125 = 1,875 us .. 43,000 + 125 = 43,125 us (the
// stimulus: 43,000 us, 1 -> 44 ms, and five of 2,000 us). The model lags both edges alike, so
// the width at the pin is Latch - Start plus the skew: +-125 us passes (inclusive), 1 ns beyond
// fails.
TEST(PowerPulseKnobs, Amci4501CycleOutputWidthFailsOneNanosecondBeyondOneThroughputOfSkew) {
  const campaign::Campaign c = load("campaigns/amci4501/amci4501_pass.toml");
  EXPECT_EQ(probe_param(c, "cycle_output_start_to_latch", "output_off_skew", Nanos{0}, c.seed), Probe::Pass);
  sweep_ns(c, "cycle_output_start_to_latch", "output_off_skew", 124'999, 125'001, 1, 125'001, +1);
  sweep_ns(c, "cycle_output_start_to_latch", "output_off_skew", -124'999, -125'001, 1, -125'001, -1);
}

// pls2700_advance_chatter one_pulse_a_turn, judged within 62 .. 65 ms: whatever the nominal width
// (the ON arc over the speed, on the 200 us update grid, 2700 manual
// seeds/002_46e90574ec92805f.txt:253), every pulse at the pin is that width plus the skew, so the
// two thresholds lie exactly the window's width apart: up - down = 65 - 62 ms + 2 ns (each side
// fails one ns beyond its edge). The pulses all have one width, read off the up threshold.
TEST(PowerPulseKnobs, Pls2700ThresholdsLieTheWindowsWidthApart) {
  const campaign::Campaign c = load("campaigns/pls2700/pls2700_advance_chatter.toml");
  PowerOptions options;
  options.checks = {"one_pulse_a_turn"};
  const PowerResult r = measure_power(c, options);
  ASSERT_EQ(r.rows.size(), 2u);
  const PowerRow& up = row_of(r, "one_pulse_a_turn", "up");
  const PowerRow& down = row_of(r, "one_pulse_a_turn", "down");
  EXPECT_EQ(up.knob, "output_off_skew");
  ASSERT_TRUE(up.threshold && down.threshold) << up.reason << down.reason;
  EXPECT_NEAR(*up.threshold - *down.threshold, 3000.002, 1e-6); // us
  const auto width_ns = static_cast<std::int64_t>(std::llround((65000.0 - (*up.threshold - 0.001)) * 1e3));
  EXPECT_EQ(width_ns % 200'000, 0) << "a whole number of 200 us updates: " << width_ns;
  EXPECT_EQ(probe_param(c, "one_pulse_a_turn", "output_off_skew", Nanos{65'000'000 - width_ns}, c.seed),
            Probe::Pass);
  EXPECT_EQ(probe_param(c, "one_pulse_a_turn", "output_off_skew", Nanos{65'000'001 - width_ns}, c.seed),
            Probe::Fail);
}

// Named, not bisected: a pulse_width check with no width limit (ans1_faults stop_fault judges
// that the stop-overrun pulse comes) and the side of a one-sided window that breaks no limit
// (pls2700_faults one_pulse_a_turn: min_us only, so a longer pulse cannot fail it).
TEST(PowerPulseKnobs, ChecksAWidthCannotFailAreNamed) {
  PowerOptions options;
  options.checks = {"stop_fault"};
  const PowerResult faults = measure_power(load("campaigns/ans1/ans1_faults.toml"), options);
  ASSERT_EQ(faults.rows.size(), 1u);
  EXPECT_NE(faults.rows[0].reason.find("no width limit"), std::string::npos) << faults.rows[0].reason;
  options.checks = {"one_pulse_a_turn"};
  const PowerResult pls = measure_power(load("campaigns/pls2700/pls2700_faults.toml"), options);
  ASSERT_EQ(pls.rows.size(), 2u);
  EXPECT_NE(row_of(pls, "one_pulse_a_turn", "up").reason.find("no max_us"), std::string::npos);
  EXPECT_FALSE(row_of(pls, "one_pulse_a_turn", "up").threshold);
  ASSERT_TRUE(row_of(pls, "one_pulse_a_turn", "down").threshold);
  EXPECT_EQ(knobs_for("ans1", "pulse_width").size(), 2u);
}

// Each knob's range is checked by the parser (the campaign's file:line:column: key: range),
// before anything runs: one value at each end of the range is accepted, one beyond it refused.
TEST(PowerKnobs, KnobValuesOutsideTheirRangeAreBadInput) {
  std::ifstream in(std::string(HILRIG_SOURCE_DIR) + "/campaigns/ssi7361/ssi7361_frame_timing.toml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string base = text.str();
  const auto with = [&](const std::string& line) {
    std::string t = base;
    const std::string anchor = "[dut.params]\n";
    t.insert(t.find(anchor) + anchor.size(), line + "\n");
    try {
      (void)campaign::parse_campaign(t, "t.toml");
      return std::string("accepted");
    } catch (const campaign::CampaignError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_EQ(with("clock_period_error = \"1us\""), "accepted");
  EXPECT_EQ(with("clock_period_error = \"-1us\""), "accepted");
  EXPECT_NE(with("clock_period_error = \"1001ns\"")
                .find("t.toml:40:22: dut.params.clock_period_error: a value in -1us .. 1us"),
            std::string::npos)
      << with("clock_period_error = \"1001ns\"");
  EXPECT_NE(with("frame_period_error = \"-101us\"").find("frame_period_error: a value in -100us .. 100us"),
            std::string::npos);
  const std::string smd = "[dut]\nmodel = \"smd23e\"\n[dut.params]\n";
  const auto smd_with = [&](const std::string& line) {
    try {
      (void)campaign::parse_campaign(smd + line + "\n[campaign]\nname = \"x\"\nend = \"1ms\"\n", "t.toml");
      return std::string("accepted");
    } catch (const campaign::CampaignError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_NE(smd_with("step_clock_error = 0.51").find("step_clock_error: a value in -0.5 .. 0.5"),
            std::string::npos)
      << smd_with("step_clock_error = 0.51");
}

} // namespace
} // namespace hilrig::power
