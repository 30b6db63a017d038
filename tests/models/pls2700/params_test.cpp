// The switchable [MODEL] choices (Params, README table) that the other tests leave at their
// defaults: fault scope, output and input delays, reverse-motion advances.
#include <gtest/gtest.h>

#include <vector>

#include "models/pls2700/error_codes.hpp"
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

} // namespace
} // namespace hilrig::models::pls2700
