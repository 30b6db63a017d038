// The device's outputs, driven through its pins on the virtual bus. Expected edge times are
// worked out by hand: with a count every P from 3 us, count n is reached at 3 us + (n-1) P;
// the next scan (every 10 us from 0) sees it 7 us later when P is a multiple of 10 us, and
// the pin follows 10 us after the scan: an output edge 17 us after the crossing.
#include <gtest/gtest.h>

#include <random>

#include "tests/models/ans1/ans1_bench.hpp"

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;
using testing::encoder_setup;
using testing::pair_output;

// Raw count = GMP, one count per ms from 3 us: count n at 3 us + (n - 1) ms.
Nanos count_time(std::int64_t n) { return 3_us + 1_ms * (n - 1); }

void one_count_per_ms(Bench& bench, std::int64_t counts) {
  bench.device().configure_position(encoder_setup(360, 360));
  bench.quadrature_run(3_us, 1_ms, counts, +1);
}

TEST(Ans1Outputs, PairEdgesLagTheCrossingByTheScan) {
  Bench bench;
  one_count_per_ms(bench, 400);
  bench.device().configure_output(9, pair_output(100, 200));
  bench.run_until(400_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[0], (Edge{count_time(100) + 17_us, Level::High})); // on at From
  EXPECT_EQ(bench.edges(9)[1], (Edge{count_time(200) + 17_us, Level::Low}));  // off at To
}

TEST(Ans1Outputs, ThroughputIsBetween10And20usForAnyCrossingTime) {
  // Property (seeded): counts at random instants; every output edge comes 10..20 us after the
  // count that crossed the setpoint (scan 10 us + output delay 10 us, L572).
  std::mt19937 rng(99);
  Bench bench;
  bench.device().configure_position(encoder_setup(360, 360));
  bench.device().configure_output(9, pair_output(1, 2));
  std::vector<Nanos> times;
  Nanos t = 0_ms;
  for (int i = 0; i < 720; ++i) {
    t += 200_us + Nanos{static_cast<std::int64_t>(rng() % 100'000)};
    times.push_back(t);
  }
  bench.quadrature_steps(times, +1);
  bench.run_until(t + 1_ms);
  // GMP reaches 1 at counts 1, 361 and 2 at counts 2, 362.
  const std::vector<Nanos> crossings{times[0], times[1], times[360], times[361]};
  ASSERT_EQ(bench.edges(9).size(), crossings.size());
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const Nanos latency = bench.edges(9)[i].time - crossings[i];
    EXPECT_GT(latency, 10_us) << i;
    EXPECT_LE(latency, 20_us) << i;
  }
}

TEST(Ans1Outputs, WrapPairThroughZero) {
  Bench bench;
  one_count_per_ms(bench, 400);
  bench.device().configure_output(10, pair_output(350, 10));
  bench.run_until(400_ms);
  // GMP 0 at power-up is inside [350, 10): on from the first scan (t = 0, pin at 10 us).
  ASSERT_EQ(bench.edges(10).size(), 4U);
  EXPECT_EQ(bench.edges(10)[0], (Edge{10_us, Level::High}));
  EXPECT_EQ(bench.edges(10)[1], (Edge{count_time(10) + 17_us, Level::Low}));
  EXPECT_EQ(bench.edges(10)[2], (Edge{count_time(350) + 17_us, Level::High}));
  EXPECT_EQ(bench.edges(10)[3], (Edge{count_time(370) + 17_us, Level::Low})); // GMP 10 of the next cycle
}

TEST(Ans1Outputs, ReversalDropsTheOutputBackAcrossFrom) {
  Bench bench;
  one_count_per_ms(bench, 105); // up to GMP 105, inside [100, 200)
  bench.device().configure_output(9, pair_output(100, 200));
  bench.quadrature_run(200_ms + 3_us, 1_ms, 10, -1); // back to 95: GMP 99 at the 6th step
  bench.run_until(300_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[1], (Edge{200_ms + 3_us + 5_ms + 17_us, Level::Low}));
}

TEST(Ans1Outputs, StitchedPairPattern) {
  // On 2, Off 1, three Ons from 100 (To = 108): on 100, off 102, on 103, off 105, on 106, off 108.
  Bench bench;
  one_count_per_ms(bench, 120);
  OutputSetup o;
  o.pairs[0] = SetpointPair{100, 108, 2, 1};
  bench.device().configure_output(11, o);
  bench.run_until(120_ms);
  const std::vector<std::pair<int, Level>> expected{{100, Level::High}, {102, Level::Low},
                                                    {103, Level::High}, {105, Level::Low},
                                                    {106, Level::High}, {108, Level::Low}};
  ASSERT_EQ(bench.edges(11).size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(bench.edges(11)[i], (Edge{count_time(expected[i].first) + 17_us, expected[i].second})) << i;
  }
}

TEST(Ans1Outputs, SeveralPairsOnOneOutput) {
  Bench bench;
  one_count_per_ms(bench, 60);
  OutputSetup o;
  o.pairs[0] = SetpointPair{10, 20, 0, 0};
  o.pairs[2] = SetpointPair{30, 40, 0, 0};
  bench.device().configure_output(12, o);
  bench.run_until(60_ms);
  ASSERT_EQ(bench.edges(12).size(), 4U);
  EXPECT_EQ(bench.edges(12)[2].time, count_time(30) + 17_us);
}

TEST(Ans1Outputs, LimitSwitchOffsetAndPreset) {
  Bench bench;
  one_count_per_ms(bench, 100);
  OutputSetup o = pair_output(100, 110);
  o.ls_offset = 50; // LSpos = GMP + 50: on for GMP 50..59
  o.ls_preset_input = 4;
  o.ls_preset_value = 0;
  bench.device().configure_output(9, o);
  bench.input_at(count_time(70) + 500_us, 4, true); // at GMP 70: LSO = 0 - 70
  bench.run_until(100_ms);
  ASSERT_GE(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[0].time, count_time(50) + 17_us);
  EXPECT_EQ(bench.edges(9)[1].time, count_time(60) + 17_us);
  EXPECT_EQ(bench.device().output_setup(9).ls_offset, -70);
  EXPECT_EQ(bench.device().ls_position(9), 100 - 70); // GMP 100 now
}

TEST(Ans1Outputs, ForcingOverridesTheProgram) {
  Bench bench;
  one_count_per_ms(bench, 150);
  bench.device().configure_output(9, pair_output(100, 200));
  bench.device().configure_output(5, pair_output(100, 200));
  bench.scheduler().at(50_ms,
                       [&bench] { bench.device().force_outputs(0b1'0001'0000'0000 | 0b1'0000, 0b1'0000); });
  bench.run_until(150_ms);
  EXPECT_TRUE(bench.device().outputs_forced());
  EXPECT_EQ(bench.pin(5), Level::High); // forced on
  EXPECT_EQ(bench.pin(9), Level::Low);  // forced off although GMP 150 is in its pair
  // The force lands at 50 ms, before that instant's scan (events at one time run in the order
  // they were scheduled): the pin follows 10 us later.
  EXPECT_EQ(bench.first_edge(5, Level::High), 50_ms + 10_us);
  EXPECT_EQ(bench.device().ls_states() & 0x100, 0x100); // the LS function is still on
}

TEST(Ans1Outputs, TimeOrPositionTimerEndsTheOutputEarly) {
  Bench bench;
  one_count_per_ms(bench, 250);
  OutputSetup o = pair_output(100, 200);
  o.timer_type = TimerType::TimeOrPosition;
  o.timer_ms = 20;
  bench.device().configure_output(9, o);
  bench.run_until(150_ms);
  EXPECT_EQ(bench.device().status_masks().timer & 0x100, 0); // held off by time (DA16 w16)
  EXPECT_EQ(bench.device().status_masks().calc & 0x100, 0x100);
  bench.run_until(250_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  // Started by the scan at count_time(100) + 7 us, expires at the scan 20 ms later.
  EXPECT_EQ(bench.edges(9)[1], (Edge{count_time(100) + 20_ms + 17_us, Level::Low}));
  EXPECT_EQ(bench.device().status_masks().timer & 0x100, 0x100); // To passed: no longer held
}

TEST(Ans1Outputs, TimeOnlyTimerOutlastsTo) {
  Bench bench;
  one_count_per_ms(bench, 250);
  OutputSetup o = pair_output(100, 110);
  o.timer_type = TimerType::TimeOnly;
  o.timer_ms = 50;
  bench.device().configure_output(9, o);
  bench.run_until(250_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[1], (Edge{count_time(100) + 50_ms + 17_us, Level::Low}));
}

TEST(Ans1Outputs, SpeedWindowEnabling) {
  // 100 RPM (4000-count cycle, 150 us per count). Window 90..110 RPM enables; 110..200 not.
  for (const auto& [low, high, on] : {std::tuple{90, 110, true}, std::tuple{110, 200, false}}) {
    Bench bench;
    bench.device().configure_position(encoder_setup(4000, 360));
    OutputSetup o = pair_output(100, 200);
    o.rpm_low = static_cast<std::int16_t>(low);
    o.rpm_high = static_cast<std::int16_t>(high);
    bench.device().configure_output(9, o);
    bench.quadrature_run(3_us, 150_us, 12000, +1);
    bench.run_until(1500_ms);
    EXPECT_EQ(bench.first_edge(9, Level::High, 600_ms).has_value(), on) << low << ".." << high;
    EXPECT_EQ((bench.device().status_masks().rpm & 0x100) != 0, on);
  }
}

TEST(Ans1Outputs, SimpleAnding) {
  Bench bench;
  one_count_per_ms(bench, 250);
  OutputSetup o = pair_output(100, 200);
  o.anding[6] = AndingMode::Simple; // input 7
  bench.device().configure_output(9, o);
  bench.input_at(150_ms + 503_us, 7, true); // scanned at 150.510 ms, pin at 150.520 ms
  bench.input_at(170_ms + 503_us, 7, false);
  bench.run_until(250_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[0].time, 150_ms + 520_us);
  EXPECT_EQ(bench.edges(9)[1].time, 170_ms + 520_us);
}

TEST(Ans1Outputs, PulseAndingLatchesForTheRestOfThePair) {
  Bench bench;
  one_count_per_ms(bench, 560);
  OutputSetup o = pair_output(100, 200);
  o.anding[4] = AndingMode::Pulse; // input 5
  bench.device().configure_output(9, o);
  bench.input_at(150_ms + 503_us, 5, true); // a short pulse inside the pair, first cycle only
  bench.input_at(151_ms + 503_us, 5, false);
  bench.run_until(560_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U); // second cycle: no pulse, stays off
  EXPECT_EQ(bench.edges(9)[0].time, 150_ms + 520_us);
  EXPECT_EQ(bench.edges(9)[1].time, count_time(200) + 17_us);
}

TEST(Ans1Outputs, WindowAndingSensesBeforeThePair) {
  Bench bench;
  one_count_per_ms(bench, 560);
  OutputSetup o = pair_output(100, 200);
  o.anding[5] = AndingMode::Window; // input 6
  o.window_low = 20;
  o.window_high = 30;
  bench.device().configure_output(9, o);
  bench.input_at(25_ms, 6, true); // inside the window in the first cycle
  bench.input_at(26_ms, 6, false);
  bench.run_until(560_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U); // second cycle: window entered, nothing sensed
  EXPECT_EQ(bench.edges(9)[0].time, count_time(100) + 17_us);
}

TEST(Ans1Outputs, ShiftRegisterEnabling) {
  // SR input 3 sensed in [10, 20), shift at 50. Cycle 1 senses a part, cycle 2 does not.
  // Output 9 (bit 1) is on at 100 in cycle 1 only; output 10 (bit 2) in cycle 2 only.
  Bench bench;
  one_count_per_ms(bench, 2 * 360 + 150);
  bench.device().configure_shift_register(ShiftRegisterSetup{3, 10, 20, 50});
  OutputSetup o = pair_output(100, 110);
  o.sr_bit = 1;
  bench.device().configure_output(9, o);
  o.sr_bit = 2;
  bench.device().configure_output(10, o);
  bench.input_at(15_ms, 3, true);
  bench.input_at(16_ms, 3, false);
  bench.run_until(2 * 360_ms + 150_ms);
  ASSERT_EQ(bench.edges(9).size(), 2U);
  EXPECT_EQ(bench.edges(9)[0].time, count_time(100) + 17_us);
  ASSERT_EQ(bench.edges(10).size(), 2U);
  EXPECT_EQ(bench.edges(10)[0].time, count_time(460) + 17_us);
  EXPECT_TRUE(bench.device().shift_register().bit(3));
}

TEST(Ans1Outputs, DisabledShiftRegisterTurnsSrOutputsOff) {
  Bench bench;
  one_count_per_ms(bench, 150);
  OutputSetup o = pair_output(100, 110);
  o.sr_bit = 5;
  bench.device().configure_output(9, o);
  bench.run_until(150_ms);
  EXPECT_TRUE(bench.edges(9).empty());
  EXPECT_EQ(bench.device().status_masks().shift_register & 0x100, 0);
}

// --- advances -------------------------------------------------------------------------------

// 100 RPM on CPC 4000 / FSC 360: count n at 3 us + (n - 1) * 150 us; the speed settles to
// 100 within the first cycle (0.625^41 after 600 ms).
Nanos count_time_100rpm(std::int64_t n) { return 3_us + 150_us * (n - 1); }

struct AdvanceRun {
  Bench bench;
  AdvanceRun(const OutputSetup& o, Variant variant = Variant::Correct, int direction = +1,
             std::int64_t counts = 3 * 4000, Nanos period = 150_us, std::uint16_t fsc = 360)
      : bench(Params{}, variant) {
    bench.device().configure_position(encoder_setup(4000, fsc));
    bench.device().configure_output(9, o);
    bench.quadrature_run(3_us, period, counts, direction);
    bench.run_until(3_us + period * counts);
  }
};

OutputSetup advanced(std::uint16_t lead, std::uint16_t trail) {
  OutputSetup o = pair_output(100, 200);
  o.advance_mode = AdvanceMode::Fixed;
  o.lead_ms = lead;
  o.trail_ms = trail;
  return o;
}

TEST(Ans1Outputs, W13LeadAdvanceOf10msIs6CountsAt100Rpm) {
  // GMP 94 = 100 - 6 first at q = ceil(94 * 4000 / 360) = 1045 (GMP 100 would be q = 1112).
  AdvanceRun run(advanced(10, 0));
  EXPECT_EQ(run.bench.device().advances(9).lead, 6);
  EXPECT_FALSE(run.bench.device().rpm_clamped());
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 1045) + 17_us);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 1200_ms), count_time_100rpm(8000 + 1045) + 17_us);
  // To is not advanced: off at GMP 200, q = ceil(200 * 4000 / 360) = 2223.
  EXPECT_EQ(run.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(4000 + 2223) + 17_us);
}

TEST(Ans1Outputs, W13LeadAdvanceOf10msIs9CountsAt150Rpm) {
  // 150 RPM: 10000 counts/s, a count every 100 us. GMP 91 first at q = ceil(91 * 4000 / 360) = 1012.
  AdvanceRun run(advanced(10, 0), Variant::Correct, +1, 3 * 4000, 100_us);
  EXPECT_EQ(run.bench.device().advances(9).lead, 9);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 400_ms), 3_us + 100_us * (4000 + 1012 - 1) + 17_us);
}

TEST(Ans1Outputs, TrailAdvanceMovesTheOffEdge) {
  // Trail 10 ms = 6 counts: off at GMP 194, q = ceil(194 * 4000 / 360) = 2156.
  AdvanceRun run(advanced(0, 10));
  EXPECT_EQ(run.bench.device().advances(9).trail, 6);
  EXPECT_EQ(run.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(4000 + 2156) + 17_us);
}

TEST(Ans1Outputs, AdvanceInReverseFiresEarlyInTheDirectionOfTravel) {
  // Turning backwards the output turns on at To and off at From; the Lead Advance Time
  // compensates the activation and the Trail the release (L888, L2621, L2622). At -100 RPM
  // lead 10 ms = 6 counts moves the turn-on edge up to 206 and trail 20 ms = 12 counts the
  // turn-off edge up to 112. After n backward counts q = 4000 - n and GMP = q * 360 / 4000:
  // GMP falls below 206 at q = 2288 (n = 1712) and below 112 at q = 1244 (n = 2756); plus
  // 4000 in the second cycle.
  AdvanceRun run(advanced(10, 20), Variant::Correct, -1);
  EXPECT_EQ(run.bench.device().speed_rpm(), -100);
  EXPECT_EQ(run.bench.device().advances(9).lead, 6);
  EXPECT_EQ(run.bench.device().advances(9).trail, 12);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(5712) + 17_us);
  EXPECT_EQ(run.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(6756) + 17_us);
}

// FSC 600 at 100 RPM: 1000 counts/s, so an advance of t ms is t counts. Pair [100, 200) is 100
// counts long and lead 10 ms moves its turn-on edge 10 counts: a trail of 110 ms meets it.
// L890: the trail advanced to the lead forces the output off, whichever way the shaft turns.
OutputSetup forced_off_pair(std::uint16_t trail) { return advanced(10, trail); }

TEST(Ans1Outputs, TrailOneCountShortOfTheLeadLeavesAOneCountPulseBothWays) {
  // Forward: on at GMP 90 (q = 600), off at GMP 91 (q = 607), second cycle.
  AdvanceRun fwd(forced_off_pair(109), Variant::Correct, +1, 3 * 4000, 150_us, 600);
  EXPECT_EQ(fwd.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 600) + 17_us);
  EXPECT_EQ(fwd.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(4000 + 607) + 17_us);
  // Reverse: the turn-on edge To 200 + 10 = 210, the turn-off edge From 100 + 109 = 209. GMP
  // falls below 210 at q = 1399 (n = 2601) and below 209 at q = 1393 (n = 2607).
  AdvanceRun rev(forced_off_pair(109), Variant::Correct, -1, 3 * 4000, 150_us, 600);
  EXPECT_EQ(rev.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 2601) + 17_us);
  EXPECT_EQ(rev.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(4000 + 2607) + 17_us);
}

TEST(Ans1Outputs, TrailAtOrPastTheLeadForcesTheOutputOffBothWays) {
  for (const std::uint16_t trail : {std::uint16_t{110}, std::uint16_t{111}}) {
    for (const int direction : {+1, -1}) {
      AdvanceRun run(forced_off_pair(trail), Variant::Correct, direction, 3 * 4000, 150_us, 600);
      EXPECT_EQ(run.bench.device().advances(9).trail, trail);
      EXPECT_FALSE(run.bench.first_edge(9, Level::High, 600_ms).has_value()) << trail << " " << direction;
    }
  }
}

TEST(Ans1Outputs, VariableAdvance) {
  // Fixed 10 ms, VAT 100 us/RPM at 100 RPM: lead = 10 + 50 * 0.1 = 15 ms = 9 counts -> GMP 91
  // at q = 1012; trail = Fixed = 6 counts -> off at q = 2156.
  OutputSetup o = pair_output(100, 200);
  o.advance_mode = AdvanceMode::Variable;
  o.lead_ms = 10;
  o.variable_us_per_rpm = 100;
  AdvanceRun run(o);
  EXPECT_EQ(run.bench.device().advances(9).lead, 9);
  EXPECT_EQ(run.bench.device().advances(9).trail, 6);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 1012) + 17_us);
  EXPECT_EQ(run.bench.first_edge(9, Level::Low, 600_ms), count_time_100rpm(4000 + 2156) + 17_us);
}

TEST(Ans1Outputs, AdvanceLongerThanACycleSetsRpmClamped) {
  // 700 ms at 100 RPM is more than the 600 ms a cycle takes.
  AdvanceRun run(advanced(700, 0), Variant::Correct, +1, 8000);
  EXPECT_TRUE(run.bench.device().rpm_clamped());
  EXPECT_EQ(run.bench.device().advances(9).lead, 359);
}

// --- fault variants ---------------------------------------------------------------------------

TEST(Ans1Variants, NamesRoundTrip) {
  for (const auto& v : kVariantNames) {
    EXPECT_EQ(variant_from_name(v.name), v.variant);
    EXPECT_EQ(variant_name(v.variant), v.name);
  }
  EXPECT_EQ(variant_from_name("nominal"), Variant::Correct);
  EXPECT_FALSE(variant_from_name("no-such-variant").has_value());
}

TEST(Ans1Variants, LateOutputsMissTheThroughput) {
  Bench correct;
  Bench late(Params{}, Variant::LateOutputs);
  for (Bench* b : {&correct, &late}) {
    one_count_per_ms(*b, 120);
    b->device().configure_output(9, pair_output(100, 200));
    b->run_until(120_ms);
  }
  EXPECT_EQ(correct.first_edge(9, Level::High), count_time(100) + 17_us);
  EXPECT_EQ(late.first_edge(9, Level::High), count_time(100) + 7_us + 100_us); // 107 us > 20 us
}

TEST(Ans1Variants, AdvanceWrongSignFiresLate) {
  // Lead 6 counts applied the wrong way: GMP 106 at q = ceil(106 * 4000 / 360) = 1178.
  AdvanceRun run(advanced(10, 0), Variant::AdvanceWrongSign);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 1178) + 17_us);
}

TEST(Ans1Variants, AdvanceWrongScaleFiresTooEarly) {
  // 12 counts instead of 6: GMP 88 at q = ceil(88 * 4000 / 360) = 978.
  AdvanceRun run(advanced(10, 0), Variant::AdvanceWrongScale);
  EXPECT_EQ(run.bench.device().advances(9).lead, 12);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 978) + 17_us);
}

TEST(Ans1Variants, SetpointOffByOneAtWrapTurnsOffLate) {
  Bench bench(Params{}, Variant::SetpointOffByOneAtWrap);
  one_count_per_ms(bench, 400);
  bench.device().configure_output(10, pair_output(350, 10));
  bench.run_until(400_ms);
  ASSERT_EQ(bench.edges(10).size(), 4U);                       // on at power-up (GMP 0), off, on at 350, off
  EXPECT_EQ(bench.edges(10)[1].time, count_time(11) + 17_us);  // correct: count_time(10)
  EXPECT_EQ(bench.edges(10)[3].time, count_time(371) + 17_us); // correct: count_time(370)
}

TEST(Ans1Variants, SpeedFilterStuckReportsNoSpeedAndNoAdvance) {
  AdvanceRun run(advanced(10, 0), Variant::SpeedFilterStuck);
  EXPECT_EQ(run.bench.device().speed_rpm(), 0);
  EXPECT_EQ(run.bench.device().advances(9).lead, 0);
  EXPECT_EQ(run.bench.first_edge(9, Level::High, 600_ms), count_time_100rpm(4000 + 1112) + 17_us);
}

TEST(Ans1Variants, OutputStuckOn) {
  Bench correct;
  Bench stuck(Params{}, Variant::OutputStuckOn);
  correct.run_until(1_ms);
  stuck.run_until(1_ms);
  EXPECT_EQ(correct.pin(1), Level::Low);
  EXPECT_EQ(stuck.pin(1), Level::High);
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Ans1Outputs, RandomPairsFollowTheHalfOpenRuleThroughTheWrap) {
  // Property (seeded): a slave position stepping forward one count every 100 us through two
  // cycles; 60 us after each step (one 40 us slave scan + 10 us output delay is at most 50 us)
  // the pin shows whether the count is in [From, To), wrapping through zero when From > To.
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 30; ++trial) {
    const auto fsc = static_cast<std::uint16_t>(20 + rng() % 200);
    const auto from = static_cast<std::uint16_t>(rng() % fsc);
    auto to = static_cast<std::uint16_t>(rng() % fsc);
    if (from == to) {
      to = static_cast<std::uint16_t>((to + 1) % fsc);
    }
    Bench bench;
    PositionSetup s;
    s.slave_mode = true;
    s.counts_per_cycle = fsc;
    s.full_scale_count = fsc;
    bench.device().configure_position(s);
    bench.device().configure_output(16, testing::pair_output(from, to));
    for (int k = 0; k < 2 * fsc; ++k) {
      const Nanos t = 100_us * (k + 1) + 3_us;
      bench.scheduler().at(t, [&bench, k] { bench.device().set_slave_position(k); });
      bench.run_until(t + 60_us);
      const int p = k % fsc;
      const bool expected = from < to ? (from <= p && p < to) : (p >= from || p < to);
      ASSERT_EQ(bench.pin(16), level_of(expected))
          << "FSC " << fsc << " pair " << from << ".." << to << " p " << p;
    }
  }
}

TEST(Ans1Device, W18HeartbeatTogglesEvery500ms) {
  Bench bench;
  bench.run_until(499_ms);
  EXPECT_FALSE(bench.device().heartbeat());
  bench.run_until(500_ms);
  EXPECT_TRUE(bench.device().heartbeat());
  bench.run_until(999_ms);
  EXPECT_TRUE(bench.device().heartbeat());
  bench.run_until(1000_ms);
  EXPECT_FALSE(bench.device().heartbeat());
}

} // namespace
} // namespace hilrig::models::ans1
