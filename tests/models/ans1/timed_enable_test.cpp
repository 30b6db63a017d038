// Timed limits (spec §4.7), output enabling (§4.8) and the shift register (§4.9), driven
// step by step with hand-made position and input sequences.
#include <gtest/gtest.h>

#include "models/ans1/enable.hpp"
#include "models/ans1/shift_register.hpp"
#include "models/ans1/timed_limit.hpp"

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;

TEST(Ans1TimedLimit, TimeOrPositionEndsAtExpiry) {
  // Pair on from t = 0 and still on at 60 ms; timer 50 ms: on until 50 ms, then held off.
  TimedLimit t;
  EXPECT_TRUE(t.step(true, 100, 0_ms, TimerType::TimeOrPosition, 50));
  EXPECT_TRUE(t.step(true, 110, 49_ms, TimerType::TimeOrPosition, 50));
  EXPECT_FALSE(t.step(true, 120, 50_ms, TimerType::TimeOrPosition, 50));
  EXPECT_TRUE(t.expired()); // DA16 w16 bit reads 0
  // To reached: off by position; the expired mark goes.
  EXPECT_FALSE(t.step(false, 200, 60_ms, TimerType::TimeOrPosition, 50));
  EXPECT_FALSE(t.expired());
  // Next From edge: a new timed on.
  EXPECT_TRUE(t.step(true, 100, 100_ms, TimerType::TimeOrPosition, 50));
}

TEST(Ans1TimedLimit, TimeOrPositionEndsAtToFirst) {
  TimedLimit t;
  EXPECT_TRUE(t.step(true, 100, 0_ms, TimerType::TimeOrPosition, 50));
  EXPECT_FALSE(t.step(false, 200, 20_ms, TimerType::TimeOrPosition, 50)); // To before 50 ms
  EXPECT_FALSE(t.expired());
}

TEST(Ans1TimedLimit, TimeOnlyExtendsBeyondTo) {
  TimedLimit t;
  EXPECT_TRUE(t.step(true, 100, 0_ms, TimerType::TimeOnly, 50));
  EXPECT_TRUE(t.step(false, 200, 20_ms, TimerType::TimeOnly, 50)); // past To: still on
  EXPECT_TRUE(t.step(false, 250, 49_ms, TimerType::TimeOnly, 50));
  EXPECT_FALSE(t.step(false, 260, 50_ms, TimerType::TimeOnly, 50));
  EXPECT_TRUE(t.expired());
}

TEST(Ans1TimedLimit, TimeOnlyRetriggerIsOffForOneCountThenRestarts) {
  // Pair 100..110 at 1 count/ms, timer 500 ms: the From edge comes back before expiry.
  TimedLimit t;
  EXPECT_TRUE(t.step(true, 100, 0_ms, TimerType::TimeOnly, 500));
  EXPECT_TRUE(t.step(false, 110, 10_ms, TimerType::TimeOnly, 500));
  EXPECT_FALSE(t.step(true, 100, 370_ms, TimerType::TimeOnly, 500));          // re-trigger: off at From
  EXPECT_FALSE(t.step(true, 100, 370_ms + 500_us, TimerType::TimeOnly, 500)); // same count
  EXPECT_TRUE(t.step(true, 101, 371_ms, TimerType::TimeOnly, 500));           // next count: on
  EXPECT_TRUE(t.step(false, 150, 800_ms, TimerType::TimeOnly, 500));          // restarted at 370 ms
  EXPECT_FALSE(t.step(false, 160, 870_ms, TimerType::TimeOnly, 500));
}

TEST(Ans1TimedLimit, ZeroTimerPassesThePairThrough) {
  TimedLimit t;
  EXPECT_TRUE(t.step(true, 0, 0_ms, TimerType::TimeOnly, 0));
  EXPECT_TRUE(t.step(true, 0, 10_s, TimerType::TimeOnly, 0));
  EXPECT_FALSE(t.step(false, 0, 11_s, TimerType::TimeOnly, 0));
}

TEST(Ans1Enable, SpeedWindowBetweenOutsideAndUnused) {
  EXPECT_TRUE(speed_enabled(0, 0, -500));    // unused
  EXPECT_TRUE(speed_enabled(100, 200, 100)); // boundaries inclusive [MODEL A40]
  EXPECT_TRUE(speed_enabled(100, 200, 200));
  EXPECT_FALSE(speed_enabled(100, 200, 99));
  EXPECT_FALSE(speed_enabled(100, 200, 201));
  EXPECT_FALSE(speed_enabled(100, 200, -150)); // reverse speed is negative
  EXPECT_TRUE(speed_enabled(-200, -100, -150));
  // Low > High: outside.
  EXPECT_TRUE(speed_enabled(200, 100, 50));
  EXPECT_TRUE(speed_enabled(200, 100, 250));
  EXPECT_FALSE(speed_enabled(200, 100, 150));
  EXPECT_FALSE(speed_enabled(200, 100, 100));
}

TEST(Ans1Enable, AndingMasksAndWindow) {
  OutputSetup s;
  s.anding[0] = AndingMode::Simple;
  s.anding[3] = AndingMode::Simple;
  s.anding[5] = AndingMode::Pulse;
  s.anding[15] = AndingMode::Window;
  EXPECT_EQ(anding_mask(s, AndingMode::Simple), 0b1001);
  EXPECT_EQ(anding_mask(s, AndingMode::Pulse), 0b100000);
  EXPECT_EQ(anding_mask(s, AndingMode::Window), 0x8000);
  EXPECT_TRUE(in_window(10, 10, 20));
  EXPECT_TRUE(in_window(20, 10, 20));
  EXPECT_FALSE(in_window(21, 10, 20));
  EXPECT_TRUE(in_window(0, 350, 5));
  EXPECT_FALSE(in_window(100, 350, 5));
}

TEST(Ans1Enable, PulseLatchHoldsForTheRestOfThePair) {
  PulseLatch latch;
  const std::uint16_t pulse = 0b10;          // input 2
  EXPECT_FALSE(latch.step(0, 0, pulse));     // inside pair 0, no pulse yet
  EXPECT_TRUE(latch.step(0, 0b10, pulse));   // pulse while inside
  EXPECT_TRUE(latch.step(0, 0, pulse));      // holds after the input drops
  EXPECT_FALSE(latch.step(-1, 0, pulse));    // left the pair
  EXPECT_FALSE(latch.step(0, 0, pulse));     // entering again clears the latch
  EXPECT_FALSE(latch.step(-1, 0b10, pulse)); // a pulse outside the pair does not count
  EXPECT_FALSE(latch.step(1, 0, pulse));
}

TEST(Ans1Enable, SeveralPulseInputsMustAllLatch) {
  PulseLatch latch;
  const std::uint16_t pulse = 0b11;
  EXPECT_FALSE(latch.step(0, 0b01, pulse));
  EXPECT_TRUE(latch.step(0, 0b10, pulse));
}

TEST(Ans1Enable, WindowLatchHoldsUntilTheWindowIsReachedAgain) {
  WindowLatch w;
  EXPECT_FALSE(w.step(false, true)); // power-up: 0; active outside does not count
  EXPECT_FALSE(w.step(true, false));
  EXPECT_TRUE(w.step(true, true));
  EXPECT_TRUE(w.step(false, false)); // holds after the window
  EXPECT_FALSE(w.step(true, false)); // entering again clears
}

TEST(Ans1ShiftRegister, CapturesInTheWindowAndShiftsAtTheShiftPosition) {
  ShiftRegister sr;
  const ShiftRegisterSetup setup{3, 10, 20, 50};
  sr.step(0, 10, true, setup, 360); // in window, input active: capture
  EXPECT_TRUE(sr.capture());
  sr.step(10, 49, false, setup, 360);
  EXPECT_FALSE(sr.bit(1));
  sr.step(49, 50, false, setup, 360); // reaches the shift position
  EXPECT_TRUE(sr.bit(1));
  EXPECT_FALSE(sr.capture());
  // Next cycle: nothing sensed -> b[1] = 0, b[2] = 1.
  sr.step(50, 359, false, setup, 360);
  sr.step(359, 5, false, setup, 360);
  sr.step(5, 60, false, setup, 360); // jumps over 50: still one shift
  EXPECT_FALSE(sr.bit(1));
  EXPECT_TRUE(sr.bit(2));
  EXPECT_EQ(sr.words()[0], 0b10);
}

TEST(Ans1ShiftRegister, InputOutsideTheWindowIsIgnoredAndReverseDoesNotShift) {
  ShiftRegister sr;
  const ShiftRegisterSetup setup{3, 10, 20, 50};
  sr.step(0, 20, true, setup, 360); // 20 is past the window [10, 20)
  EXPECT_FALSE(sr.capture());
  sr.step(20, 15, true, setup, 360);
  sr.step(60, 45, false, setup, 360); // backwards over the shift position
  EXPECT_FALSE(sr.bit(1));
  EXPECT_FALSE(sr.bit(2));
  EXPECT_TRUE(sr.capture());
}

TEST(Ans1ShiftRegister, Bit256FallsOffTheEnd) {
  ShiftRegister sr;
  const ShiftRegisterSetup setup{1, 0, 10, 100};
  sr.step(0, 5, true, setup, 360);
  sr.step(5, 100, false, setup, 360); // b[1] = 1
  for (int cycle = 0; cycle < 255; ++cycle) {
    sr.step(100, 300, false, setup, 360);
    sr.step(300, 50, false, setup, 360);
    sr.step(50, 100, false, setup, 360);
  }
  EXPECT_TRUE(sr.bit(256));
  EXPECT_EQ(sr.words()[15], 0x8000); // DA20 word 19 bit 15 = b[256]
  sr.step(100, 300, false, setup, 360);
  sr.step(300, 50, false, setup, 360);
  sr.step(50, 100, false, setup, 360);
  for (int n = 1; n <= 256; ++n) {
    EXPECT_FALSE(sr.bit(n)) << n;
  }
}

TEST(Ans1ShiftRegister, CrossingForward) {
  EXPECT_TRUE(crossed_forward(359, 0, 0, 360));
  EXPECT_TRUE(crossed_forward(358, 2, 0, 360));
  EXPECT_FALSE(crossed_forward(0, 5, 0, 360));   // leaving the mark is not reaching it
  EXPECT_FALSE(crossed_forward(5, 359, 0, 360)); // backwards
  EXPECT_FALSE(crossed_forward(7, 7, 7, 360));
}

} // namespace
} // namespace hilrig::models::ans1
