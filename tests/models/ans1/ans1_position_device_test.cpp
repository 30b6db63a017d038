// The device's position and speed, driven through its pins on the virtual bus: quadrature
// (4X, Z ignored), resolver (sampled at the excitation peaks, 4,096 counts/turn), slave mode,
// presets, the 14.6 ms speed filter and resolver-fault behaviour of the outputs.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "tests/models/ans1/ans1_bench.hpp"

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;
using testing::encoder_setup;
using testing::pair_output;

TEST(Ans1Device, W07EncoderPositionCounts4XAndWrapsBackwards) {
  Bench bench;
  bench.device().configure_position(encoder_setup(2000, 1440));
  // 500 forward quadrature states = 500 counts (4X): 500 * 1440 / 2000 = 360.
  bench.quadrature_run(3_us, 100_us, 500, +1);
  bench.run_until(60_ms);
  EXPECT_EQ(bench.device().transducer_count(), 500);
  EXPECT_EQ(bench.device().gmp(), 360);
  // 600 back: raw -100 -> q = 1900 -> 1900 * 1440 / 2000 = 1368.
  bench.quadrature_run(61_ms, 100_us, 600, -1);
  bench.run_until(130_ms);
  EXPECT_EQ(bench.device().transducer_count(), -100);
  EXPECT_EQ(bench.device().gmp(), 1368);
}

TEST(Ans1Device, ZChannelIsIgnored) {
  Bench bench;
  bench.device().configure_position(encoder_setup(360, 360));
  bench.quadrature_run(3_us, 100_us, 40, +1);
  for (int k = 0; k < 10; ++k) {
    bench.scheduler().at(5_ms + 100_us * k,
                         [&bench, k] { bench.bus().line("ans1.Z").driver().set(level_of(k % 2 == 0)); });
  }
  bench.run_until(10_ms);
  EXPECT_EQ(bench.device().gmp(), 40);
}

TEST(Ans1Device, W02ResolverQuarterTurnIs90) {
  Bench bench;
  bench.resolver_at(1024.0);
  bench.run_until(1_ms);
  EXPECT_FALSE(bench.device().resolver_fault());
  EXPECT_EQ(bench.device().gmp(), 90);
}

TEST(Ans1Device, ResolverCountDirectionReversesGmp) {
  Bench bench;
  PositionSetup s;
  s.count_ccw = true; // CntDir = 1: raw = 4096 - angle
  bench.device().configure_position(s);
  bench.resolver_at(1024.0);
  bench.run_until(1_ms);
  EXPECT_EQ(bench.device().gmp(), 270); // 3072 * 360 / 4096
}

TEST(Ans1Device, ResolverDecodesEveryCountOfATurn) {
  // Property (seeded): an angle synthesized at count k reads k, for any TR in 0.9..1.0.
  std::mt19937 rng(7);
  PositionSetup s;
  s.full_scale_count = 4096; // GMP = raw count
  for (int i = 0; i < 40; ++i) {
    Bench bench;
    bench.device().configure_position(s);
    const auto k = static_cast<int>(rng() % 4096);
    const double tr = 0.9 + 0.1 * static_cast<double>(rng() % 1000) / 1000.0;
    bench.resolver_at(k, tr);
    bench.run_until(500_us);
    EXPECT_EQ(bench.device().gmp(), k) << "TR " << tr;
  }
}

TEST(Ans1Device, ResolverTracksTurnsForANonPowerOfTwoCycle) {
  // 10 turns/s from angle 0. The stators are sampled at the excitation peaks (every 100 us
  // at 5 kHz, the first at 50 us); at the 250 ms scan the last peak was 249.95 ms, where the
  // angle is 4096 * 2.4995 = 10237.95 counts -> 10237. CPC 1000, FSC 360: q = 237 -> 85.
  Bench bench;
  PositionSetup s;
  s.counts_per_cycle = 1000;
  bench.device().configure_position(s);
  bench.resolver([](Nanos t) { return 4096.0 * 10.0 * t.seconds(); });
  bench.run_until(250_ms);
  EXPECT_EQ(bench.device().transducer_count(), 10237);
  EXPECT_EQ(bench.device().gmp(), 85);
}

TEST(Ans1Device, ResolverStandingStillHasNoSpeed) {
  // The first reading after power-up is an absolute angle, not motion.
  Bench bench;
  bench.resolver_at(1024.0);
  bench.run_until(100_ms);
  EXPECT_EQ(bench.device().speed(), 0.0);
}

TEST(Ans1Device, ResolverSpeedIsCyclesPerMinute) {
  // 10 turns/s on CPC 4096 = 600 RPM. Each reading is at most one excitation half period
  // (100 us = 4.1 counts at 40,960 counts/s) old, so one measurement is within 4.2 RPM.
  Bench bench;
  bench.resolver([](Nanos t) { return 1000.0 + 4096.0 * 10.0 * t.seconds(); });
  bench.run_until(1_s);
  EXPECT_NEAR(bench.device().speed(), 600.0, 4.2);
}

TEST(Ans1Device, SlaveModeTakesPositionDirectlyWithA50usThroughput) {
  Bench bench;
  PositionSetup s;
  s.slave_mode = true;
  s.counts_per_cycle = 360;
  bench.device().configure_position(s);
  bench.device().configure_output(9, pair_output(100, 200));
  // Slave scans every 40 us from the reconfiguration (0): a position arriving at 1003 us is
  // scanned at 1040 us, the output follows 10 us later: 47 us, within the 50 us figure.
  bench.scheduler().at(1003_us, [&bench] { bench.device().set_slave_position(100); });
  bench.run_until(2_ms);
  EXPECT_EQ(bench.device().gmp(), 100);
  EXPECT_EQ(bench.first_edge(9, Level::High), 1050_us);
  EXPECT_EQ(bench.device().scan_period(), 40_us);
}

TEST(Ans1Device, MachinePresetByInputEdge) {
  Bench bench;
  PositionSetup s = encoder_setup(360, 360);
  s.preset_input = 2;
  s.preset_value = 50;
  bench.device().configure_position(s);
  bench.quadrature_run(3_us, 100_us, 10, +1);
  bench.input_at(2_ms, 2, true); // inactive -> active: GMP becomes MPV
  bench.run_until(3_ms);
  EXPECT_EQ(bench.device().gmp(), 50);
  EXPECT_EQ(bench.device().position_setup().scaled_offset, 40); // 50 - 10
  // Only the edge presets: 5 more counts while the input stays active.
  bench.quadrature_run(4_ms, 100_us, 5, +1);
  bench.run_until(5_ms);
  EXPECT_EQ(bench.device().gmp(), 55);
}

TEST(Ans1Device, MachinePresetByNetworkLoadsTheValue) {
  Bench bench;
  bench.device().configure_position(encoder_setup(360, 360));
  bench.quadrature_run(3_us, 100_us, 300, +1);
  bench.run_until(31_ms);
  bench.device().preset_machine(std::uint16_t{10}); // CB2 bits 14 and 11
  EXPECT_EQ(bench.device().gmp(), 10);
  EXPECT_EQ(bench.device().position_setup().preset_value, 10);
  EXPECT_EQ(bench.device().position_setup().scaled_offset, 10 - 300); // -290: within +-359
  bench.quadrature_run(32_ms, 100_us, 60, +1);
  bench.run_until(40_ms);
  EXPECT_EQ(bench.device().gmp(), 70);
}

TEST(Ans1Device, InputPolarityAndForcing) {
  Bench bench;
  PositionSetup s;
  s.input_active_state = 0b100; // input 3 active when no current flows
  bench.device().configure_position(s);
  bench.run_until(100_us);
  EXPECT_EQ(bench.device().input_states(), 0b100);
  bench.set_input(3, true);
  bench.set_input(1, true);
  bench.run_until(200_us);
  EXPECT_EQ(bench.device().input_states(), 0b001);
  EXPECT_EQ(bench.device().electrical_inputs(), 0b101);
  bench.device().force_inputs(0b11, 0b10); // input 1 forced off, input 2 forced on
  bench.run_until(300_us);
  EXPECT_EQ(bench.device().input_states(), 0b010);
}

// --- speed -------------------------------------------------------------------------------

// 100 RPM on a 4000-count cycle is 6666.7 counts/s: one count every 150 us.
void run_at_100rpm(Bench& bench, std::int64_t counts, int direction, Nanos first = 3_us) {
  bench.quadrature_run(first, 150_us, counts, direction);
}

TEST(Ans1Device, SpeedUpdatesEvery14p6msWithTheDefaultFilter) {
  Bench bench;
  bench.device().configure_position(encoder_setup(4000, 360));
  run_at_100rpm(bench, 20000, +1);
  bench.run_until(14'599_us);
  EXPECT_EQ(bench.device().speed(), 0.0); // nothing before the first update
  bench.run_until(14'600_us);
  // Counts at 3 + 150 k us <= 14600 us: k = 0..97, 98 counts. X = 98/4000 cycles in
  // 14.6 ms = 100.685 RPM; S = (1 - 0.625) X.
  const double x = 98.0 / 4000.0 / 0.0146 * 60.0;
  EXPECT_NEAR(bench.device().speed(), 0.375 * x, 1e-9);
  bench.run_until(1200_ms);
  EXPECT_EQ(bench.device().speed_rpm(), 100);
}

TEST(Ans1Device, SpeedIsNegativeInReverse) {
  Bench bench;
  bench.device().configure_position(encoder_setup(4000, 360));
  run_at_100rpm(bench, 8000, -1);
  bench.run_until(1200_ms);
  EXPECT_EQ(bench.device().speed_rpm(), -100);
}

TEST(Ans1Device, TimeOfRotationIsTheLastCycleInTenthsOfMs) {
  // 1 count per ms on a 360-count cycle: a cycle takes 360 ms = 3600 tenths.
  Bench bench;
  bench.device().configure_position(encoder_setup(360, 360));
  bench.quadrature_run(3_us, 1_ms, 800, +1);
  bench.run_until(800_ms);
  EXPECT_EQ(bench.device().time_of_rotation(), 3600);
}

// "The time it took for the shaft to complete its last rotation" (L2537) names no direction,
// and reverse rotation is a normal case (L2535): 1 count per ms backwards on a 360-count cycle
// reads 3600 too. Forward at 1 ms a count (3600), then backwards at 2 ms a count: the first
// backward roll-over after a forward one completes no rotation and keeps 3600; the next, 360
// counts (720 ms) later, reads 7200.
TEST(Ans1Device, TimeOfRotationIsMeasuredInReverseToo) {
  Bench backward;
  backward.device().configure_position(encoder_setup(360, 360));
  backward.quadrature_run(3_us, 1_ms, 800, -1);
  backward.run_until(800_ms);
  EXPECT_EQ(backward.device().time_of_rotation(), 3600);

  Bench both;
  both.device().configure_position(encoder_setup(360, 360));
  both.quadrature_run(3_us, 1_ms, 800, +1);
  both.quadrature_run(801_ms + 3_us, 2_ms, 900, -1);
  both.run_until(800_ms);
  EXPECT_EQ(both.device().time_of_rotation(), 3600);
  both.run_until(1600_ms); // backward roll-over at 961 ms only
  EXPECT_EQ(both.device().time_of_rotation(), 3600);
  both.run_until(1700_ms); // and at 1681 ms
  EXPECT_EQ(both.device().time_of_rotation(), 7200);
}

// --- transducer fault ----------------------------------------------------------------------

TEST(Ans1Device, ResolverFaultTurnsOutputsOffAndLatchesUntilClearErrors) {
  Bench bench;
  bench.device().configure_output(1, pair_output(80, 100)); // GMP 90 is inside
  bench.resolver_at(1024.0);
  bench.run_until(1_ms);
  EXPECT_EQ(bench.pin(1), Level::High);
  bench.resolver_at(1024.0, 0.0); // open stators
  bench.run_until(2_ms);
  EXPECT_TRUE(bench.device().resolver_fault());
  EXPECT_EQ(bench.pin(1), Level::Low); // HoldOuts = 0: all outputs off
  bench.resolver_at(1024.0);
  bench.run_until(3_ms);
  EXPECT_TRUE(bench.device().resolver_fault()); // XFltLatch = 0: latched
  EXPECT_EQ(bench.pin(1), Level::Low);
  bench.device().clear_errors();
  bench.run_until(4_ms);
  EXPECT_FALSE(bench.device().resolver_fault());
  EXPECT_EQ(bench.pin(1), Level::High);
}

TEST(Ans1Device, ResolverFaultClearsItselfWithXFltLatchSet) {
  Bench bench;
  PositionSetup s;
  s.fault_auto_clear = true;
  bench.device().configure_position(s);
  bench.resolver_at(1024.0, 0.0);
  bench.run_until(1_ms);
  EXPECT_TRUE(bench.device().resolver_fault());
  bench.resolver_at(1024.0);
  bench.run_until(2_ms);
  EXPECT_FALSE(bench.device().resolver_fault());
}

TEST(Ans1Device, ResolverFaultWithHoldOutsKeepsTheLastStates) {
  Bench bench;
  PositionSetup s;
  s.hold_outputs_on_fault = true;
  bench.device().configure_position(s);
  bench.device().configure_output(1, pair_output(80, 100));
  bench.resolver_at(1024.0);
  bench.run_until(1_ms);
  bench.resolver_at(1024.0, 2.0); // amplitude too high: also a fault
  bench.run_until(1200_us);       // next excitation peak at 1050 us
  ASSERT_TRUE(bench.device().resolver_fault());
  bench.device().configure_output(1, pair_output(200, 300)); // the LS program would turn it off
  bench.run_until(2_ms);
  EXPECT_TRUE(bench.device().resolver_fault());
  EXPECT_EQ(bench.pin(1), Level::High);
}

TEST(Ans1Device, OneOpenStatorPairIsAFault) {
  // Only the cosine pair open, shaft at 0 counts: sin = 0 as well -> amplitude 0.
  Bench bench;
  bench.resolver_at(0.0);
  bench.bus().analog("ans1.COS").set_waveform([](Nanos) { return 0.0; });
  bench.run_until(1_ms);
  EXPECT_TRUE(bench.device().resolver_fault());
}

TEST(Ans1Device, EncoderModeIgnoresTheResolverInputs) {
  Bench bench;
  bench.device().configure_position(encoder_setup(360, 360)); // no stator signals at all
  bench.run_until(1_ms);
  EXPECT_FALSE(bench.device().resolver_fault());
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Ans1Device, W16TimeOfRotationIn100usUnits) {
  // A 4-count cycle rolling over at 4.003 ms and 16.303 ms (both scanned 7 us later): the
  // last rotation took 12.3 ms, reported as 123.
  Bench bench;
  bench.device().configure_position(testing::encoder_setup(4, 4));
  bench.quadrature_steps({1_ms + 3_us, 2_ms + 3_us, 3_ms + 3_us, 4_ms + 3_us, 5_ms + 3_us, 6_ms + 3_us,
                          7_ms + 3_us, 16_ms + 303_us},
                         +1);
  bench.run_until(20_ms);
  EXPECT_EQ(bench.device().time_of_rotation(), 123);
}

TEST(Ans1Device, TimeOfRotationSaturatesAt16Bits) {
  // Slave positions stepping 0 -> 120 -> 240 -> 0 on a 360-count cycle: roll-overs at the
  // scans after 3 ms and after 7 s. 6997 ms is more than 6553.5 ms: reported 65535 (A46).
  Bench bench;
  PositionSetup s;
  s.slave_mode = true;
  s.counts_per_cycle = 360;
  bench.device().configure_position(s);
  const std::vector<std::pair<Nanos, std::int64_t>> steps{{1_ms, 120}, {2_ms, 240}, {3_ms, 360},
                                                          {3_s, 480},  {6_s, 600},  {7_s, 720}};
  for (const auto& [t, count] : steps) {
    bench.scheduler().at(t, [&bench, c = count] { bench.device().set_slave_position(c); });
  }
  bench.run_until(7100_ms);
  EXPECT_EQ(bench.device().time_of_rotation(), 65535);
}

TEST(Ans1Device, DieProtectionFaultOutputTakesTheOutputAndItsVariantNeverCounts) {
  // Monitor on input 5, Normally True, fault output 12 (no LS program): the output is on while
  // the counter is 0 and drops at the first active -> inactive edge (L1072, L1077). The
  // die_check_never_counts variant keeps the counter at 0 and the output on.
  MonitorSetup monitors;
  monitors.die.monitors[4].fault_output = 12;
  monitors.die.monitors[4].mode = DieCheckMode::NormallyTrue;
  for (Variant v : {Variant::Correct, Variant::DieProtectionNeverCounts}) {
    Bench bench(Params{}, v);
    bench.device().configure_position(testing::encoder_setup(360, 360)); // no resolver fault
    bench.device().configure_monitors(monitors);
    bench.input_at(1_ms + 3_us, 5, true);
    bench.run_until(4_ms);
    EXPECT_EQ(bench.pin(12), Level::High) << variant_name(v);
    bench.input_at(5_ms + 3_us, 5, false);
    bench.run_until(10_ms);
    const bool correct = v == Variant::Correct;
    EXPECT_EQ(bench.device().monitors().die().fault_count(5), correct ? 1 : 0) << variant_name(v);
    EXPECT_EQ(bench.pin(12), correct ? Level::Low : Level::High) << variant_name(v);
  }
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Ans1Device, HostSwitchToSlaveModeScansEvery40us) {
  // CB2 through the host words (spec §5.3): word 1 bit 2 = SlaveMode; command word
  // T (bit 15) | Apply w1 (bit 7) | block 2 = 0x8082, written first with T = 0.
  Params every_period;
  every_period.exact_scan = true; // counts scans: none skipped
  Bench bench(every_period);
  bench.run_until(1_ms);
  bench.device().host().write(1, 0x0004);
  bench.device().host().write(0, 0x0082);
  bench.device().host().write(0, 0x8082);
  bench.run_until(2_ms);
  EXPECT_TRUE(bench.device().position_setup().slave_mode);
  EXPECT_EQ(bench.device().scan_period(), 40_us);
  const std::uint64_t before = bench.device().scans();
  bench.run_until(6_ms);
  EXPECT_EQ(bench.device().scans() - before, 100U); // 4 ms / 40 us: one scan chain
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Ans1Device, ResolverTurningBackwardsGivesNegativeSpeed) {
  // Decreasing angle with CntDir = 0 (L2535): -5 turns/s = -300 RPM, within a 100 us-old
  // reading (2,048 counts/s * 100 us = 2.05 counts -> 2.1 RPM per measurement).
  Bench bench;
  bench.resolver([](Nanos t) { return 3000.0 - 4096.0 * 5.0 * t.seconds(); });
  bench.run_until(1_s);
  EXPECT_NEAR(bench.device().speed(), -300.0, 2.1);
}

TEST(Ans1Device, CountDirectionHasNoEffectOnAnEncoder) {
  Bench bench;
  PositionSetup s = testing::encoder_setup(360, 360);
  s.count_ccw = true;
  bench.device().configure_position(s);
  bench.quadrature_run(3_us, 100_us, 30, +1);
  bench.run_until(5_ms);
  EXPECT_EQ(bench.device().gmp(), 30);
}

TEST(Ans1Device, OutputPresetWithValueLoadsItFirst) {
  // CB3 bits 14 and 9: LSPV = 200, then LSO = 200 - GMP (GMP 30): LSpos reads 200.
  Bench bench;
  bench.device().configure_position(testing::encoder_setup(360, 360));
  bench.quadrature_run(3_us, 100_us, 30, +1);
  bench.run_until(5_ms);
  bench.device().preset_output(3, std::uint16_t{200});
  EXPECT_EQ(bench.device().output_setup(3).ls_preset_value, 200);
  EXPECT_EQ(bench.device().output_setup(3).ls_offset, 170);
  EXPECT_EQ(bench.device().ls_position(3), 200);
}

TEST(Ans1Device, SetupRoundTrips) {
  // Property (seeded): whatever is configured is what setup() reports back.
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    Ans1Setup s;
    s.position.sensor = rng() % 2 == 0 ? SensorType::Resolver : SensorType::Quadrature;
    s.position.counts_per_cycle = static_cast<std::uint16_t>(2 + rng() % 4095);
    s.position.full_scale_count = static_cast<std::uint16_t>(1 + rng() % s.position.counts_per_cycle);
    s.position.rpm_filter = static_cast<std::uint16_t>(rng() % 65536);
    s.position.input_active_state = static_cast<std::uint16_t>(rng() % 65536);
    for (int n = 1; n <= kOutputCount; ++n) {
      OutputSetup& o = s.output(n);
      o.pairs[0] = SetpointPair{static_cast<std::uint16_t>(rng() % s.position.full_scale_count),
                                static_cast<std::uint16_t>(rng() % s.position.full_scale_count), 0, 0};
      o.advance_mode = AdvanceMode::Fixed;
      o.lead_ms = static_cast<std::uint16_t>(rng() % 32768);
      o.timer_ms = static_cast<std::uint16_t>(rng() % 32768);
      o.sr_bit = static_cast<std::uint16_t>(rng() % 257);
      o.anding[rng() % 16] = AndingMode::Pulse;
    }
    s.shift_register = ShiftRegisterSetup{static_cast<std::uint8_t>(rng() % 17), 1, 2, 3};
    s.monitors.brake.input = static_cast<std::uint8_t>(rng() % 17);
    Scheduler scheduler;
    Ans1 device(scheduler);
    device.configure(s);
    EXPECT_EQ(device.setup(), s);
  }
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Ans1Device, BrakeStartOverrunOutputAndItsNeverFaultsVariant) {
  // Brake input 2 released at 10 ms; the shaft moves from 200 ms at a count per 100 us, so it
  // passes 2 * CSC = 20 counts at about 202 ms: a start time near 192 ms, over the 50 ms limit.
  // The start-overrun output 13 is on while healthy and off on the fault ([MODEL] A5); the
  // brake_never_faults variant measures the time but leaves the output on.
  MonitorSetup monitors;
  monitors.brake.input = 2;
  monitors.brake.complete_stop_count = 10;
  monitors.brake.start_time_limit_ms = 50;
  monitors.brake.start_overrun_output = 13;
  for (Variant v : {Variant::Correct, Variant::BrakeNeverFaults}) {
    Bench bench(Params{}, v);
    bench.device().configure_position(testing::encoder_setup(4096, 360));
    bench.device().configure_monitors(monitors);
    bench.input_at(10_ms + 3_us, 2, true);
    bench.quadrature_run(200_ms + 3_us, 100_us, 100, +1);
    // Sampled on the 11 ms tick: elapsed 50 ms (at the limit) at 61 ms, exceeded at 62 ms --
    // the output goes off by the clock while the press has not moved yet
    // (seeds/000_08a2edf5547d4d1e.txt:1056: "turn off a fault output if the starting time is
    // exceeded").
    bench.run_until(61_ms + 500_us);
    EXPECT_EQ(bench.pin(13), Level::High) << variant_name(v);
    bench.run_until(62_ms + 500_us);
    EXPECT_EQ(bench.pin(13), v == Variant::Correct ? Level::Low : Level::High) << variant_name(v);
    EXPECT_EQ(bench.device().monitors().brake().status().completed_starts, 0U) << variant_name(v);
    bench.run_until(300_ms);
    EXPECT_EQ(bench.device().monitors().brake().status().completed_starts, 1U) << variant_name(v);
    EXPECT_GT(bench.device().monitors().brake().status().start_time_ms, 50) << variant_name(v);
    EXPECT_EQ(bench.pin(13), v == Variant::Correct ? Level::Low : Level::High) << variant_name(v);
  }
}

TEST(Ans1Device, BrakeReleasedRightAfterCommandBlock8IsTimed) {
  // The start time runs from the brake input's inactive-to-active transition (L1054-L1056);
  // DA19 w3 is the position where it made it (L2614). CB8 (input 5, CSC 10, start limit 300 ms
  // on output 6, stop limit 50 ms on output 7) is executed by the scan at 1.010 ms with input 5
  // inactive; the monitor's first 1 ms tick is at 2 ms. A release at any time after that scan
  // -- before the first tick, at it, after it -- is timed: the shaft never moves, so the start
  // exceeds its limit and output 6 goes off (L1056, [MODEL A5]); the released position is GMP =
  // SMO = 100 (L780). A release that scan already reads is no transition after programming.
  const Nanos executed = 1010_us;
  HostWords cb8{};
  cb8[0] = static_cast<std::uint16_t>(kTransmitBit | 0x3F00U | 8U);
  cb8[1] = 5;
  cb8[2] = 10;
  cb8[3] = 300;
  cb8[4] = 6;
  cb8[5] = 50;
  cb8[6] = 7;
  for (const Params& params : {Params{}, testing::every_period()}) {
    for (const Nanos after :
         {-10_us, -1_ns, 0_ns, 1_ns, 10_us, 500_us, 990_us - 1_ns, 990_us, 990_us + 1_ns, 1990_us, 2_ms}) {
      Bench bench(params);
      PositionSetup position = testing::encoder_setup(4096, 360);
      position.scaled_offset = 100;
      bench.device().configure_position(position);
      bench.scheduler().at(1005_us, [&bench, &cb8] { bench.device().host().write_block(cb8); });
      bench.input_at(executed + after, 5, true);
      bench.run_until(500_ms);
      const bool released_after_programming = after > 0_ns;
      const BrakeMonitor& brake = bench.device().monitors().brake();
      ASSERT_EQ(brake.setup().input, 5);
      EXPECT_EQ(brake.status().released_position, released_after_programming ? 100 : 0) << after.count();
      EXPECT_EQ(brake.start_fault(), released_after_programming) << after.count();
      EXPECT_EQ(bench.pin(6), released_after_programming ? Level::Low : Level::High) << after.count();
      EXPECT_EQ(bench.pin(7), Level::High) << after.count();
    }
  }
}

} // namespace
} // namespace hilrig::models::ans1

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;

TEST(Ans1Device, WiresOnlyTheMappedPins) {
  // A campaign wiring: encoder A/B and output 9 on lines of its own naming; the rest unwired.
  Scheduler scheduler;
  virt::VirtualBus bus(scheduler);
  const std::map<std::string, std::string, std::less<>> wiring{
      {"A", "enc.a"}, {"B", "enc.b"}, {"OUT9", "plc.x9"}};
  const Ans1Pins pins = wire_pins_by_map(bus, wiring);
  EXPECT_EQ(pins.quad_z, nullptr);
  EXPECT_EQ(pins.inputs[0], nullptr);
  EXPECT_NE(pins.outputs[8], nullptr);
  Ans1 device(scheduler, pins);
  device.configure_position(testing::encoder_setup(360, 360));
  device.configure_output(9, testing::pair_output(2, 5));
  scheduler.at(1_ms, [&bus] { bus.line("enc.a").driver().set(Level::High); });
  scheduler.at(2_ms, [&bus] { bus.line("enc.b").driver().set(Level::High); });
  scheduler.run_until(3_ms);
  EXPECT_EQ(device.gmp(), 2); // two forward quadrature states
  EXPECT_EQ(bus.line("plc.x9").level(), Level::High);
}

} // namespace
} // namespace hilrig::models::ans1
