// The switchable [MODEL] choices (Params, README table) that the other tests leave at their
// defaults: fault scope, output and input delays, reverse-motion advances.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "models/pls2700/error_codes.hpp"
#include "models/pls2700/params_check.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

TEST(Pls2700Params, TransducerFaultScope) {
  // §7.20: with OA 4 and channel 2 open, the default turns off all eight outputs; the
  // alternative only outputs 5-8 (channel 2's).
  for (bool all : {true, false}) {
    Params p;
    p.fault_turns_off_all_outputs = all;
    Bench b(ModelVariant::M2742, p);
    b.hold(1, 15, 360);
    auto& ch2 = b.hold(2, 15, 360);
    ASSERT_EQ(b.btw({0x8804, 0x0403}), error::kNone);
    for (std::uint16_t n = 1; n <= 8; ++n) {
      ASSERT_EQ(b.btw({static_cast<std::uint16_t>(0xC001 | (n << 4)), 0x0000, 0x0010, 0x0020}), error::kNone);
    }
    b.run_for(1_ms);
    EXPECT_EQ(b.device().output_states(), 0xFF);
    signals::ResolverFaults open;
    open.cos_open = true;
    open.sin_open = true;
    ch2.set_faults(open);
    b.run_for(1_ms);
    EXPECT_EQ(b.device().output_states(), all ? 0x00 : 0x0F);
  }
}

TEST(Pls2700Params, OutputDelayShiftsEveryEdge) {
  // d_drv = 50 us: the 25 ms edge of the no-advance window (advance_test.cpp) at 25.05 ms.
  Params p;
  p.output_delay = 50_us;
  Bench b(ModelVariant::M2741, p);
  ASSERT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x0000, 0x2000, 0x3000}), error::kNone);
  b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, 32.0 / 8192.0 / 0.0002));
  b.run_until(30_ms);
  ASSERT_EQ(b.edges(1).size(), 1u);
  EXPECT_EQ(b.edges(1)[0].time, 25'050_us);
}

TEST(Pls2700Params, ReverseAdvanceSignedOrDisabled) {
  // Shaft backwards 32 raw counts per update from raw 8191.5: MP = 4095 - 16k (SF 4096),
  // v = -80 counts/ms. Pair 2000..3000, a_on = a_off = 10 ms.
  // Disabled: the plain window: on when MP <= 2999 (k 69, 13.8 ms), off when MP <= 1999
  // (k 131, 26.2 ms). Signed (R-ADV-6 option A): both points move up by 800 -> window
  // [2800, 3800): on at MP <= 3799 (k 19, 3.8 ms), off at MP <= 2799 (k 81, 16.2 ms).
  for (ReverseAdvance mode : {ReverseAdvance::Disabled, ReverseAdvance::Signed}) {
    Params p;
    p.reverse_advance = mode;
    Bench b(ModelVariant::M2741, p);
    ASSERT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x1010, 0x2000, 0x3000}), error::kNone);
    b.shaft(1, signals::angle_at_constant_speed(8191.5 / 8192.0, -32.0 / 8192.0 / 0.0002));
    b.run_until(30_ms);
    ASSERT_EQ(b.edges(1).size(), 2u);
    const bool disabled = mode == ReverseAdvance::Disabled;
    EXPECT_EQ(b.edges(1)[0].time, disabled ? 13'800_us : 3'800_us);
    EXPECT_EQ(b.edges(1)[1].time, disabled ? 26'200_us : 16'200_us);
  }
}

TEST(Pls2700Params, InputDelayOn2742_18) {
  // T_ON = 3 ms: a rising edge at 10 ms acts at the first update at or after 13 ms
  // (k0 = 33, 13.2 ms); with 16 LS counts per update the pair 160..320 is on at k 43 (17.2 ms).
  Params p;
  p.input_delay = 3_ms;
  Bench b(ModelVariant::M2742_18, p);
  b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, 32.0 / 8192.0 / 0.0004));
  b.hold(2, 0, 360);
  ASSERT_EQ(b.btw({0x8801, 0x4096, 0x8808, 0x1000, 0xC011, 0x0000, 0x0160, 0x0320}), error::kNone);
  b.input_at(10_ms, 1, true);
  b.run_until(30_ms);
  ASSERT_EQ(b.edges(1).size(), 2u);
  EXPECT_EQ(b.edges(1)[0].time, 17'200_us);
  EXPECT_EQ(b.edges(1)[1].time, 21'200_us);
}

// The update period is "always 200 microseconds for single channel units and 400
// microseconds for two channel units" (L377, L455-L457). Every update samples at a reference
// peak only when the half period 1/(2f) divides it: f a multiple of 1/(2 * 200 us) = 2,500 Hz
// or 1/(2 * 400 us) = 1,250 Hz (README "Decoder").
TEST(Pls2700Params, ReferenceStepIsOneOverTwiceTheUpdatePeriod) {
  EXPECT_EQ(reference_step_hz(200_us), 2'500);
  EXPECT_EQ(reference_step_hz(400_us), 1'250);
  for (const double hz : {2'500.0, 5'000.0, 7'500.0, 10'000.0}) {
    EXPECT_TRUE(reference_fits_update(hz, 200_us)) << hz;
    EXPECT_TRUE(reference_fits_update(hz, 400_us)) << hz; // a divisor of 200 us divides 400 us
    EXPECT_FALSE(reference_fits_update(hz - 1.0, 200_us)) << hz;
    EXPECT_FALSE(reference_fits_update(hz + 1.0, 200_us)) << hz;
    // The nearest doubles either side: exact, no float rounding onto the grid.
    EXPECT_FALSE(reference_fits_update(std::nextafter(hz, 0.0), 200_us)) << hz;
    EXPECT_FALSE(reference_fits_update(std::nextafter(hz, 1e9), 200_us)) << hz;
  }
  for (const double hz : {1'250.0, 3'750.0, 6'250.0, 8'750.0}) {
    EXPECT_TRUE(reference_fits_update(hz, 400_us)) << hz;
    EXPECT_FALSE(reference_fits_update(hz, 200_us)) << hz;
    EXPECT_FALSE(reference_fits_update(hz - 1.0, 400_us)) << hz;
    EXPECT_FALSE(reference_fits_update(hz + 1.0, 400_us)) << hz;
  }
  EXPECT_FALSE(reference_fits_update(12'500.0, 200_us)); // on the grid, above the 10 kHz offered
  EXPECT_FALSE(reference_fits_update(3'000.0, 200_us));  // the examiner's 359 us case
}

TEST(Pls2700Params, ParamsThatDoNotGoTogetherAreRefusedByTheModel) {
  Params off_grid;
  off_grid.excitation_hz = 3'000.0;
  EXPECT_THROW(Bench(ModelVariant::M2741, off_grid), std::invalid_argument);
  const auto conflict = params_conflict(ModelVariant::M2741, off_grid);
  ASSERT_TRUE(conflict.has_value());
  EXPECT_EQ(conflict->fields.front(), "excitation_hz");
  EXPECT_NE(
      conflict->expected.find("a multiple of 2500 Hz up to 10000: 2500, 5000, 7500, 10000 (got 3000 Hz)"),
      std::string::npos)
      << conflict->expected;
  // The transducer-fault band is closed (README "Decoder"): one point is a band, a minimum a
  // hair above the maximum is none.
  Params band;
  band.min_stator_ratio = band.max_stator_ratio = 1.0;
  EXPECT_FALSE(params_conflict(ModelVariant::M2742, band).has_value());
  EXPECT_NO_THROW(Bench(ModelVariant::M2742, band));
  band.min_stator_ratio = std::nextafter(1.0, 2.0);
  const auto empty = params_conflict(ModelVariant::M2742, band);
  ASSERT_TRUE(empty.has_value());
  EXPECT_EQ(empty->fields, (std::vector<std::string_view>{"min_stator_ratio", "max_stator_ratio"}));
  EXPECT_THROW(Bench(ModelVariant::M2742, band), std::invalid_argument);
}

// At every reference the model takes, a crossing 1 us after an update shows at the next
// update: the latency is the update period less 1 us, the longest L377/L457 allow ("New
// Position Throughput Time 200 uSec: 2731, 2731-04, 2741 Modules 400 uSec: 2732, 2732-04,
// 2742, 2742-18"). SF 4096 (MP = raw / 2), pair 2000..3000 on output 1; the shaft turns 100 raw
// counts a ms from raw 2999.9, so it crosses raw 4000 (MP 2000) at 10.001 ms and raw 6000 at
// 30.001 ms; updates fall on every multiple of the period (update_phase 0).
TEST(Pls2700Params, EveryTakenReferenceKeepsTheThroughputOfOneUpdate) {
  const auto check = [](ModelVariant model, double hz, Nanos period) {
    SCOPED_TRACE(::testing::Message() << traits(model).name << " at " << hz << " Hz");
    Params p;
    p.excitation_hz = hz;
    Bench b(model, p);
    ASSERT_EQ(b.btw({0x8801, 0x4096, 0xC011, 0x0000, 0x2000, 0x3000}), error::kNone);
    // The stators carry ref(t) * sin/cos(2 pi angle) (§2.4), written here: signals::Resolver
    // takes only 2.2 .. 7 kHz. Channel 2 (two-channel modules) stands still at 0.
    const Excitation* ref = &b.device().excitation();
    const auto stators = [&](int channel, signals::AngleFunction turns) {
      b.bus().analog("pls." + sin_pin_name(channel)).set_waveform([ref, turns](Nanos t) {
        return ref->value(t) * std::sin(2.0 * std::numbers::pi * turns(t));
      });
      b.bus().analog("pls." + cos_pin_name(channel)).set_waveform([ref, turns](Nanos t) {
        return ref->value(t) * std::cos(2.0 * std::numbers::pi * turns(t));
      });
    };
    constexpr double kCountsPerSecond = 100'000.0;
    stators(1, signals::angle_at_constant_speed(2999.9 / 8192.0, kCountsPerSecond / 8192.0));
    if (traits(model).channels == 2) stators(2, [](Nanos) { return 0.0; });
    b.run_until(40_ms);
    ASSERT_EQ(b.edges(1).size(), 2u);
    EXPECT_EQ(b.edges(1)[0].time - 10'001_us, period - 1_us);
    EXPECT_EQ(b.edges(1)[1].time - 30'001_us, period - 1_us);
  };
  for (const double hz : {2'500.0, 5'000.0, 7'500.0, 10'000.0}) check(ModelVariant::M2741, hz, 200_us);
  for (const double hz : {1'250.0, 2'500.0, 3'750.0, 5'000.0, 6'250.0, 7'500.0, 8'750.0, 10'000.0})
    check(ModelVariant::M2742, hz, 400_us);
}

} // namespace
} // namespace hilrig::models::pls2700
