// Every move type, timed from the outside through the step train (spec §3). Common numbers:
// v_s = 100 steps/s, A = D = 10 steps/ms/s (10,000 steps/s²), 2048 steps/turn; the ramp
// 100 → 1100 steps/s takes 60 steps and 0.1 s (examples file, "handy P0 ramps").
#include <string>

#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

using Smd23eMoves = Smd23eBench;

TEST_F(Smd23eMoves, RelativeTrapezoidTimingFromTheStepTrain) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  // 60 steps in 0.1 s, 880 at 1100 steps/s (0.8 s), 60 in 0.1 s: done at 1.0 s.
  EXPECT_EQ(dut.step_position(100_ms), 60);
  EXPECT_EQ(dut.step_position(500_ms) - dut.step_position(400_ms), 110); // peak 1100 steps/s
  run_to(50_ms);
  EXPECT_EQ(sw1() & 0x7F, sw1::kAccelerating | sw1::kMovingCw);
  run_to(500_ms);
  EXPECT_EQ(sw1() & 0x7F, sw1::kMovingCw);
  EXPECT_EQ(position_word(), 500);
  run_to(950_ms);
  EXPECT_EQ(sw1() & 0x7F, sw1::kDecelerating | sw1::kMovingCw);
  run_to(999'999_us);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to(1'000'001_us);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word(), 1000);
  EXPECT_EQ(dut.shaft_steps(sched.now()), 1000);
}

TEST_F(Smd23eMoves, RelativeTriangleTimingAndPeak) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 100, .vp = 5000});
  // v_peak = √1,010,000 = 1004.99 steps/s; T = 2·(v_peak − 100)/10,000 = 0.1809975 s.
  const double peak = std::sqrt(1'010'000.0);
  const double t_end = 2.0 * (peak - 100.0) / 10'000.0;
  EXPECT_NEAR(dut.runs().back().motion.velocity(Nanos::from_seconds(t_end / 2)), peak, 1e-3);
  run_to_s(t_end - 1e-6);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to_s(t_end + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 100);
}

TEST_F(Smd23eMoves, NegativeRelativeMovesCcw) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = -1000});
  run_to(500_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_EQ(position_word(), -500);
  run_to(2_s);
  EXPECT_EQ(position_word(), -1000);
}

TEST_F(Smd23eMoves, SCurveMovesTakeTheRampFactors) {
  configure();
  // J = 1: each ramp 0.2 s / 120 steps; cruise 760/1100 s. T = 0.4 + 0.690909 s.
  command(msw::kRelative, kDrive, MoveWords{.value = 1000, .word9 = 1});
  const double t1 = 0.4 + 760.0 / 1100.0;
  run_to_s(t1 - 1e-6);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to_s(t1 + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(dut.input_words()[9], 1); // input word 9 echoes the jerk value
  // J = 2 (half linear): each ramp 0.1333 s / 80 steps; cruise 840/1100 s.
  const double start = sched.now().seconds();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000, .word9 = 2});
  const double t2 = start + 2.0 * 0.4 / 3.0 + 840.0 / 1100.0;
  run_to_s(t2 - 1e-6);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to_s(t2 + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 2000);
}

TEST_F(Smd23eMoves, M11RotaryTableRelativeAndAbsolute) {
  // 3600 steps/turn: 10 steps per degree.
  configure(ConfigWords{.steps_per_turn = 3600});
  for (std::int64_t expected : {300, 600, 900}) {
    command(msw::kRelative, kDrive, MoveWords{.value = 300}); // 30°
    run_to(sched.now() + 2_s);
    EXPECT_EQ(position_word(), expected);
  }
  preset(900);                                               // absolute moves need a valid position
  command(msw::kAbsolute, kDrive, MoveWords{.value = 1800}); // 180°: +900 CW
  run_to(sched.now() + 10_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  run_to(sched.now() + 2_s);
  EXPECT_EQ(position_word(), 1800);
  preset(2500);
  command(msw::kAbsolute, kDrive, MoveWords{.value = 1800}); // −700 CCW
  run_to(sched.now() + 10_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  run_to(sched.now() + 2_s);
  EXPECT_EQ(position_word(), 1800);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eMoves, AbsoluteMoveNeedsAValidPosition) {
  configure();
  command(msw::kAbsolute, kDrive, MoveWords{.value = 500});
  run_to(1_s);
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_EQ(dut.step_position(sched.now()), 0);
  command(msw::kResetErrors);
  EXPECT_FALSE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid)); // Reset Errors does not validate the position
  preset(0);
  EXPECT_FALSE(bit1(sw1::kPositionInvalid));
  command(msw::kAbsolute, kDrive, MoveWords{.value = 500});
  run_to(3_s);
  EXPECT_EQ(position_word(), 500);
}

TEST_F(Smd23eMoves, M10EncoderMoveDeceleratesFromTheEncoderTarget) {
  configure(ConfigWords{.control = ccw::kEncoderEnable});
  command(msw::kPresetEncoder, kDrive, MoveWords{.value = 5000});
  EXPECT_EQ(encoder_word(), 5000);
  // Relative encoder move of 11,000 counts = 22,000 steps at 2048 steps/turn.
  command(msw::kRelative, kDrive | lsw::kEncoderMove, MoveWords{.value = 11'000});
  const Nanos decel = when_at(22'000);
  run_to(decel - 1_ms);
  EXPECT_FALSE(bit1(sw1::kDecelerating));
  run_to(decel);
  EXPECT_EQ(encoder_word(), 16'000); // deceleration starts at encoder 16,000
  run_to(decel + 1_ms);
  EXPECT_TRUE(bit1(sw1::kDecelerating));
  run_to(sched.now() + 1_s);
  // The stop lies beyond 16,000: 60 decel steps = 30 counts.
  EXPECT_EQ(position_word(), 22'060);
  EXPECT_EQ(encoder_word(), 16'030);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eMoves, M10AbsoluteEncoderMoveToTheSameTargetGivesTheSameFigure) {
  configure(ConfigWords{.control = ccw::kEncoderEnable});
  preset(0);
  command(msw::kPresetEncoder, kDrive, MoveWords{.value = 5000});
  command(msw::kAbsolute, kDrive | lsw::kEncoderMove, MoveWords{.value = 16'000});
  run_to(30_s);
  EXPECT_EQ(position_word(), 22'060);
  EXPECT_EQ(encoder_word(), 16'030);
}

TEST_F(Smd23eMoves, JogRunsUntilItsBitDrops) {
  configure();
  command(msw::kJogCw);
  run_to(1_s);
  EXPECT_EQ(position_word(), 60 + 990); // 60 ramp steps, then 0.9 s at 1100
  write(0);                             // bit returns to 0: controlled stop, 60 steps in 0.1 s
  run_to(1099_ms);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to(1101_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 1110);
}

TEST_F(Smd23eMoves, JogSpeedChangesOnTheFly) {
  configure();
  command(msw::kJogCcw);
  run_to(1_s);                                        // at 1100 steps/s
  write(msw::kJogCcw, kDrive, MoveWords{.vp = 2100}); // ramp 1100 → 2100 at A: 160 steps, 0.1 s
  run_to(1100_ms);
  run_to(1200_ms);
  EXPECT_EQ(dut.step_position(1200_ms) - dut.step_position(1100_ms), -210); // now 2100 steps/s
  write(msw::kJogCcw, kDrive, MoveWords{.vp = 2100, .accel = 0});           // invalid: keeps old values
  EXPECT_TRUE(bit2(sw2::kInvalidJogChange));
  run_to(1300_ms);
  EXPECT_EQ(dut.step_position(1300_ms) - dut.step_position(1200_ms), -210);
}

TEST_F(Smd23eMoves, HoldAndResumeARelativeMove) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms); // at 500, 1100 steps/s
  write(msw::kHold);
  run_to(600_ms); // 60 decel steps in 0.1 s
  EXPECT_TRUE(bit1(sw1::kHoldState));
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 560);
  run_to(1_s);
  command(msw::kResume, kDrive, MoveWords{.vp = 1100}); // target unchanged: 440 steps left
  EXPECT_FALSE(bit1(sw1::kHoldState));
  // 60 + 320 + 60 steps: 0.1 + 320/1100 + 0.1 s.
  const double t_end = 1.0 + 0.2 + 320.0 / 1100.0;
  run_to_s(t_end - 1e-6);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to_s(t_end + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 1000);
}

TEST_F(Smd23eMoves, HeldMoveIsCancelledByAnotherMove) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  write(msw::kHold);
  run_to(1_s);
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(2_s);
  EXPECT_EQ(position_word(), 660);
  command(msw::kResume);
  EXPECT_TRUE(bit1(sw1::kCommandError)); // nothing held any more
}

// An Immediate Stop "cannot be restarted" (L943): one sent while the move is held ends it, so
// a Resume finds nothing (Command Error, no step); the shaft stood still, so the position
// stays valid (L2450: invalid only when the bit is set during a move).
TEST_F(Smd23eMoves, ImmediateStopEndsAHeldMoveForGood) {
  configure();
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  write(msw::kHold);
  run_to(1_s);
  ASSERT_TRUE(bit1(sw1::kHoldState));
  ASSERT_EQ(position_word(), 560);
  command(msw::kImmediateStop);
  EXPECT_FALSE(bit1(sw1::kHoldState));
  EXPECT_FALSE(bit1(sw1::kPositionInvalid));
  command(msw::kResume, kDrive, MoveWords{.vp = 1100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  run_to(2_s);
  EXPECT_EQ(position_word(), 560);
}

TEST_F(Smd23eMoves, HoldAndResumeAJog) {
  configure();
  command(msw::kJogCw);
  run_to(1_s);
  write(msw::kHold); // bit 2 rises while the jog bit drops: Hold (spec §9 #26)
  run_to(1200_ms);
  EXPECT_TRUE(bit1(sw1::kHoldState));
  EXPECT_EQ(position_word(), 1110);
  command(msw::kResume, kDrive, MoveWords{.vp = 2100});
  run_to(2_s);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  EXPECT_EQ(dut.step_position(2_s) - dut.step_position(1900_ms), 210);
}

// A held move "can be resumed if an error did not occur while the move was in its Hold state"
// (L1224; Jog L1239, Absolute/Relative/Encoder L1247): after a programming error (a Relative
// command out of range, a Resume out of range) or an input error (E-Stop) while held, Resume
// finds nothing to resume -- a Command Error ([A] spec §3.11), no step -- even once the error
// is reset; Reset Errors alone is no error, and the move resumes after it.
enum class DuringHold { Nothing, BadMove, BadResume, EStop };
class Smd23eErrorWhileHeld : public Smd23eBench, public ::testing::WithParamInterface<DuringHold> {};

TEST_P(Smd23eErrorWhileHeld, ForbidsTheResume) {
  const DuringHold during = GetParam();
  configure(ConfigWords{.control = 0b101'000'000}); // input 3: E-Stop
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  write(msw::kHold);
  run_to(600_ms);
  ASSERT_TRUE(bit1(sw1::kHoldState));
  ASSERT_EQ(position_word(), 560);
  switch (during) {
  case DuringHold::Nothing:
    break;
  case DuringHold::BadMove:
    command(msw::kRelative, kDrive, MoveWords{.value = 100, .vp = 0, .accel = 0}); // L2860
    EXPECT_TRUE(bit1(sw1::kCommandError));
    break;
  case DuringHold::BadResume:
    command(msw::kResume, kDrive, MoveWords{.vp = 3'000'000}); // v_p above 2,999,999 (L2494)
    EXPECT_TRUE(bit1(sw1::kCommandError));
    break;
  case DuringHold::EStop:
    at(700_ms, in3, Level::High);
    at(800_ms, in3, Level::Low);
    run_to(900_ms);
    EXPECT_TRUE(bit1(sw1::kInputError));
    break;
  }
  command(msw::kResetErrors);
  EXPECT_FALSE(bit1(sw1::kCommandError));
  command(msw::kResume, kDrive, MoveWords{.vp = 1100});
  run_to(3_s);
  if (during == DuringHold::Nothing) {
    EXPECT_FALSE(bit1(sw1::kCommandError));
    EXPECT_EQ(position_word(), 1000); // the target, as HoldAndResumeARelativeMove
  } else {
    EXPECT_TRUE(bit1(sw1::kCommandError)); // nothing held
    EXPECT_EQ(position_word(), 560);
  }
}

INSTANTIATE_TEST_SUITE_P(Errors, Smd23eErrorWhileHeld,
                         ::testing::Values(DuringHold::Nothing, DuringHold::BadMove, DuringHold::BadResume,
                                           DuringHold::EStop));

// A jog moves "as long as the command is active" and stops when its bit returns to 0 (L1012,
// L1033); a resumed jog's command is the Resume bit ([MODEL], spec §9 #26): clearing it stops
// the jog at D (2,100 -> 100 steps/s at 10,000 steps/s^2: 0.2 s, 220 steps), and it stays
// stopped.
TEST_F(Smd23eMoves, AResumedJogStopsWhenTheResumeBitFalls) {
  configure();
  command(msw::kJogCw);
  run_to(1_s);
  write(msw::kHold);
  run_to(1200_ms);
  command(msw::kResume, kDrive, MoveWords{.vp = 2100});
  run_to(2_s); // at 2,100 steps/s since 1.4 s
  const std::int64_t at_stop = position_word();
  write(0, kDrive, MoveWords{.vp = 2100});
  run_to(2100_ms);
  EXPECT_TRUE(bit1(sw1::kDecelerating));
  run_to(2201_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word() - at_stop, 220);
  run_to(3_s);
  EXPECT_EQ(position_word() - at_stop, 220);
}

class Smd23eRegistration : public Smd23eBench {
protected:
  void SetUp() override {
    configure(ConfigWords{.control = 0b100}); // input 1: Stop Jog/Registration
  }
};

TEST_F(Smd23eRegistration, M26StopInputAlreadyActiveGivesMinPlusStoppingDistance) {
  in1.set(Level::High);
  // S = 200 steps, M = 500 steps (words 8–9 = 0, 500).
  command(msw::kJogCw, kDrive | lsw::kRegistration, MoveWords{.value = 200, .word8 = 0, .word9 = 500});
  // M is reached at 0.1 + 440/1100 = 0.5 s; then S ≥ 60: cruise 140, decel 60.
  const double t_end = 0.5 + 140.0 / 1100.0 + 0.1;
  run_to_s(t_end - 1e-6);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to_s(t_end + 1e-6);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 700);
}

TEST_F(Smd23eRegistration, ShortStoppingDistanceEndsAbruptly) {
  command(msw::kJogCw, kDrive | lsw::kRegistration, MoveWords{.value = 30});
  at(500_ms, in1, Level::High); // at 500 steps, 1100 steps/s
  // 30 steps < 60 needed: decelerate at D for 30 steps, v_end = √(1100² − 2·10⁴·30) = 781.0.
  const double t_end = 0.5 + (1100.0 - std::sqrt(610'000.0)) / 10'000.0;
  run_to_s(t_end - 1e-6);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to_s(t_end + 1e-6);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word(), 530);
}

TEST_F(Smd23eRegistration, StopConditionsBeforeTheMinimumDistanceAreIgnored) {
  command(msw::kJogCw, kDrive | lsw::kRegistration,
          MoveWords{.value = 100, .word8 = 1, .word9 = 0}); // M = 1000
  at(200_ms, in1, Level::High);
  at(250_ms, in1, Level::Low); // pulse gone before M
  run_to(2_s);
  EXPECT_TRUE(bit1(sw1::kMovingCw)); // still running
  write(0);                          // bit drops after M: S = 100 more steps
  const std::int64_t trigger = position_word();
  run_to(3_s);
  EXPECT_EQ(position_word(), trigger + 100);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eRegistration, HoldStopsWithoutTailAndCannotResume) {
  command(msw::kJogCw, kDrive | lsw::kRegistration, MoveWords{.value = 500});
  run_to(500_ms);
  write(msw::kHold);
  run_to(1_s);
  EXPECT_EQ(position_word(), 560); // decel only, no 500-step tail
  EXPECT_FALSE(bit1(sw1::kHoldState));
  command(msw::kResume);
  EXPECT_TRUE(bit1(sw1::kCommandError));
}

TEST_F(Smd23eRegistration, JogStopInputCapturesTheEncoder) {
  configure(ConfigWords{.control = 0b100 | ccw::kEncoderEnable});
  command(msw::kJogCw);
  at(500_ms, in1, Level::High); // step 500 = 250 counts at 2048 steps/turn
  run_to(1_s);
  EXPECT_EQ(captured_word(), 250);
  EXPECT_EQ(position_word(), 560);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

class Smd23eEdgeOnlyStopInput : public Smd23eBench {
protected:
  Smd23eEdgeOnlyStopInput() : Smd23eBench(Params{.stop_input_level_sensitive = false}) {}
};

TEST_F(Smd23eEdgeOnlyStopInput, AStopInputAlreadyActiveDoesNotEndTheRegistrationMove) {
  configure(ConfigWords{.control = 0b100});
  in1.set(Level::High);
  command(msw::kJogCw, kDrive | lsw::kRegistration, MoveWords{.value = 200, .word8 = 0, .word9 = 500});
  run_to(2_s);
  EXPECT_TRUE(bit1(sw1::kMovingCw)); // with edge-only sensing the M + S rule of L1068 does not apply
}

TEST_F(Smd23eMoves, BlendMoveRunsSegmentsBackToBack) {
  configure();
  command(msw::kProgramMove);
  EXPECT_TRUE(bit1(sw1::kProgramMode));
  EXPECT_TRUE(bit1(sw1::kTransmitSegment));
  for (std::int32_t vp : {1100, 2100}) {
    write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = vp});
    EXPECT_FALSE(bit1(sw1::kTransmitSegment));
    write(msw::kProgramMove, kDrive, MoveWords{.value = 1000, .vp = vp});
    EXPECT_TRUE(bit1(sw1::kTransmitSegment));
  }
  write(0);
  EXPECT_FALSE(bit1(sw1::kProgramMode));
  EXPECT_FALSE(bit1(sw1::kCommandError));
  command(msw::kRunAssembled);
  // Segment 1: 60 ramp + 940 at 1100 (0.854545 s). Segment 2 starts at step 1000:
  // 1100 → 2100 at A (160 steps, 0.1 s), cruise 620 at 2100, decel 2100 → 100 (220, 0.2 s).
  const double t_boundary = 0.1 + 940.0 / 1100.0;
  EXPECT_EQ(dut.step_position(Nanos::from_seconds(t_boundary + 1e-9)), 1000);
  const double t_end = t_boundary + 0.1 + 620.0 / 2100.0 + 0.2;
  run_to_s(t_boundary + 0.05);
  EXPECT_TRUE(bit1(sw1::kAccelerating));
  run_to_s(t_end - 1e-6);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to_s(t_end + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 2000);
}

TEST_F(Smd23eMoves, HoldOnABlendUsesTheCurrentSegmentsDecelerationAndEndsTheMove) {
  configure();
  command(msw::kProgramMove);
  write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = 1100});
  write(msw::kProgramMove);
  write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = 2100, .decel = 20});
  write(msw::kProgramMove);
  write(0);
  command(msw::kRunAssembled);
  // Segment 2 cruises at 2100 from 1160 steps at t = 0.1 + 940/1100 + 0.1 s.
  const double t_cruise = 0.2 + 940.0 / 1100.0;
  run_to(1200_ms);
  write(msw::kHold);
  // Segment 2's D = 20,000 steps/s²: (2100² − 100²)/40,000 = 110 steps in 0.1 s.
  const double at_hold = 1160.0 + 2100.0 * (1.2 - t_cruise);
  run_to(1'299_ms);
  EXPECT_FALSE(bit1(sw1::kStopped));
  run_to(1'301_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word(), static_cast<std::int64_t>(std::floor(at_hold + 110.0)));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  command(msw::kResume, kDrive, MoveWords{.vp = 1100});
  EXPECT_TRUE(bit1(sw1::kCommandError)); // a held assembled move cannot be resumed
  command(msw::kResetErrors);
  command(msw::kRunAssembled); // but it stays stored and runs again
  run_to(5_s);
  EXPECT_EQ(position_word(), static_cast<std::int64_t>(std::floor(at_hold + 110.0)) + 2000);
}

TEST_F(Smd23eMoves, AtMostSixteenSegments) {
  configure();
  command(msw::kProgramMove);
  for (int i = 0; i < 17; ++i) {
    write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = 1100 + 100 * i});
    write(msw::kProgramMove);
    EXPECT_EQ(bit1(sw1::kCommandError), i == 16) << i; // the 17th is refused
  }
}

TEST_F(Smd23eMoves, DwellMoveStopsAndWaitsBetweenSegments) {
  configure();
  command(msw::kProgramMove);
  write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 300, .vp = 1100});
  write(msw::kProgramMove);
  write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = -300, .vp = 2100});
  write(msw::kProgramMove);
  write(0);
  command(msw::kRunAssembled, kDrive | lsw::kDwellType, MoveWords{.word9 = 500});
  // Segment 1: 60 + 180 + 60 steps, 0.2 + 180/1100 s. Dwell 0.5 s.
  const double t1 = 0.2 + 180.0 / 1100.0;
  run_to_s(t1 + 0.25);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 300);
  // Segment 2: −300 steps, a triangle: v_pk = √(100² + 300·10⁴) = √3,010,000.
  const double t2 = t1 + 0.5 + 2.0 * (std::sqrt(3'010'000.0) - 100.0) / 10'000.0;
  run_to_s(t1 + 0.5 + 0.01);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  run_to_s(t2 - 1e-6);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to_s(t2 + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 0);
}

class Smd23eDwellAfterLast : public Smd23eBench {
protected:
  Smd23eDwellAfterLast() : Smd23eBench(Params{.dwell_after_last_segment = true}) {}
};

TEST_F(Smd23eDwellAfterLast, MoveCompleteComesOneDwellAfterTheLastSegment) {
  configure();
  command(msw::kProgramMove);
  write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 300, .vp = 1100});
  write(msw::kProgramMove);
  write(0);
  command(msw::kRunAssembled, kDrive | lsw::kDwellType, MoveWords{.word9 = 500});
  const double t1 = 0.2 + 180.0 / 1100.0; // as above
  run_to_s(t1 + 0.5 - 1e-6);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  run_to_s(t1 + 0.5 + 1e-6);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eMoves, IndexedMoveStartsOnEachStartInputEdge) {
  configure(ConfigWords{.control = 0b011}); // input 1: Start Indexed Move
  command(msw::kRelative, kDrive | lsw::kIndexed, MoveWords{.value = 100});
  run_to(1_s);
  EXPECT_EQ(position_word(), 0); // armed, not run
  in1.set(Level::High);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  in1.set(Level::Low); // the falling edge does not stop it
  run_to(2_s);
  EXPECT_EQ(position_word(), 100);
  in1.set(Level::High); // data unchanged: the edge re-runs the move
  run_to(3_s);
  EXPECT_EQ(position_word(), 200);
  in1.set(Level::Low);
  write(0, kDrive | lsw::kIndexed); // command cleared: disarmed
  in1.set(Level::High);
  run_to(4_s);
  EXPECT_EQ(position_word(), 200);
}

class Smd23eHoming : public Smd23eBench {
protected:
  void SetUp() override {
    configure(ConfigWords{.control = 0b110 | ccw::kEncoderEnable}); // input 1: Home
  }
};

TEST_F(Smd23eHoming, ProfileAHomeInputOnly) {
  // The Home cam is active for shaft positions ≥ 1000.
  command(msw::kHomeCw);
  at(when_at(1000), in1, Level::High); // 0.954545 s
  sched.run_until_idle();              // decel to 1060, 2 s pause, reverse: open-ended
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_EQ(dut.runs().back().motion.start(), Nanos::from_seconds(0.1 + 940.0 / 1100.0 + 0.1 + 2.0));
  at(when_at(999), in1, Level::Low); // Home active → inactive going CCW
  sched.run_until_idle();            // decel 60 steps to 939, 2 s pause, creep CW
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  at(when_at(1000), in1, Level::High); // 61 steps at v_s: 0.61 s
  sched.run_until_idle();
  EXPECT_EQ(dut.step_position(sched.now()), 1000);
  EXPECT_EQ(position_word(), 0);
  EXPECT_EQ(encoder_word(), 0);
  EXPECT_TRUE(bit1(sw1::kHomed));
  EXPECT_FALSE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kMoveComplete)); // homing never sets Move Complete
  const double t_reverse = 0.1 + 940.0 / 1100.0 + 0.1 + 2.0;
  const double t_done = t_reverse + 0.1 + 1.0 / 1100.0 + 0.1 + 2.0 + 0.61;
  EXPECT_NEAR(sched.now().seconds(), t_done, 2e-6);
}

TEST_F(Smd23eHoming, ProfileAMirroredForCcwFindHome) {
  // The Home cam is active for shaft positions ≤ −1000.
  command(msw::kHomeCcw);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  at(when_at(-1000), in1, Level::High);
  sched.run_until_idle(); // stop at −1060, 2 s, reverse CW
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  at(when_at(-999), in1, Level::Low);
  sched.run_until_idle(); // stop at −939, 2 s, creep CCW
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  at(when_at(-1000), in1, Level::High);
  sched.run_until_idle();
  EXPECT_EQ(dut.step_position(sched.now()), -1000);
  EXPECT_EQ(position_word(), 0);
  EXPECT_TRUE(bit1(sw1::kHomed));
}

TEST_F(Smd23eHoming, ProfileAStartsReversedWhenHomeIsAlreadyActive) {
  in1.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
}

TEST_F(Smd23eHoming, ProfileBProximityBit) {
  configure(ConfigWords{.control = 0b110 | ccw::kHomeProximityEnable});
  command(msw::kHomeCw);
  in1.set(Level::High); // Home ignored before the proximity bit
  in1.set(Level::Low);
  run_to(500_ms);                                    // at 500
  write(msw::kHomeCw, kDrive | lsw::kHomeProximity); // decel to v_s: 60 steps
  run_to(700_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  at(when_at(600), in1, Level::High); // creeping at v_s since 560
  sched.run_until_idle();
  EXPECT_EQ(dut.step_position(sched.now()), 600);
  EXPECT_EQ(position_word(), 0);
  EXPECT_TRUE(bit1(sw1::kHomed));
}

TEST_F(Smd23eHoming, ProfileCLimitInTheSearchDirection) {
  configure(ConfigWords{.control = 0b001'110}); // input 1 Home, input 2 CW limit
  // A narrow Home switch, active between positions −200 and −100, behind the start.
  command(msw::kHomeCw);
  at(500_ms, in2, Level::High); // CW limit at 500: immediate stop, no error
  run_to(600_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_FALSE(bit1(sw1::kInputError));
  EXPECT_EQ(dut.step_position(sched.now()), 500);
  run_to(2'499_ms);
  EXPECT_TRUE(bit1(sw1::kStopped)); // the 2 s pause
  run_to(2'501_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  in2.set(Level::Low);
  at(when_at(-100), in1, Level::High); // entering the switch going CCW: not the step-5 edge
  at(when_at(-201), in1, Level::Low);  // leaving it: active → inactive ends step 5
  sched.run_until_idle();
  EXPECT_TRUE(bit1(sw1::kMovingCw));         // step 7: creeping back after the second pause
  EXPECT_EQ(dut.runs().back().origin, -261); // 60 decel steps past −201
  at(when_at(-200), in1, Level::High);
  sched.run_until_idle();
  EXPECT_EQ(dut.step_position(sched.now()), -200);
  EXPECT_EQ(position_word(), 0);
  EXPECT_TRUE(bit1(sw1::kHomed));
}

TEST_F(Smd23eHoming, OppositeLimitDuringHomingIsAnInputError) {
  configure(ConfigWords{.control = 0b010'110}); // input 2: CCW limit
  command(msw::kHomeCw);
  at(300_ms, in2, Level::High);
  run_to(400_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kInputError));
  EXPECT_FALSE(bit1(sw1::kHomed));
}

TEST_F(Smd23eMoves, FindHomeWithoutAHomeInputIsACommandError) {
  configure();
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kStopped));
}

// Profile A's last step: "Creep CW at v_s. Stop on Home inactive→active" (L1331–1335, spec
// §3.9 step 7), position := 0 there (L1275). The Home edge stops the step train at once: a
// creep step is issued only if it was due at or before the edge, to the ns (a step due at the
// edge itself comes first). Home is already active at the command, so the profile starts at the
// reverse search (L1335); it goes inactive at 500 ms; after the deceleration and the 2 s pause
// (L1327) the creep's step k is due at its start + k / v_s: step v_s 1 s into it.
struct CreepPhase {
  std::int32_t vs; // steps/s
  std::int64_t offset_ns;
};

class Smd23eCreepPhase : public Smd23eBench, public ::testing::WithParamInterface<CreepPhase> {};

TEST_P(Smd23eCreepPhase, ACreepStepIsIssuedOnlyIfDueAtOrBeforeTheHomeEdge) {
  const CreepPhase c = GetParam();
  configure(ConfigWords{.control = 0b110, .vs = c.vs}); // input 1: Home
  in1.set(Level::High);
  command(msw::kHomeCw);
  at(500_ms, in1, Level::Low);
  run_to(3_s);
  ASSERT_TRUE(bit1(sw1::kMovingCw));
  const Nanos creep = dut.runs().back().motion.start();
  // The decel 1100 → v_s at 10,000 steps/s² and the pause: the creep's start as the manual has it.
  ASSERT_NEAR(creep.seconds(), 0.5 + (1100.0 - c.vs) / 10'000.0 + 2.0, 1e-6);
  const std::int64_t before = dut.step_position(creep);
  const std::int64_t step = c.vs; // the step due 1 s into the creep
  const Nanos due = creep + 1_s;
  at(due + Nanos{c.offset_ns}, in1, Level::High);
  run_to(due + 1_s);
  EXPECT_TRUE(bit1(sw1::kHomed));
  EXPECT_EQ(dut.step_position(sched.now()) - before, c.offset_ns < 0 ? step - 1 : step);
}

INSTANTIATE_TEST_SUITE_P(Phases, Smd23eCreepPhase,
                         ::testing::Values(CreepPhase{1000, -2}, CreepPhase{1000, -1}, CreepPhase{1000, 0},
                                           CreepPhase{1000, 1}, CreepPhase{100, -11}, CreepPhase{100, -10},
                                           CreepPhase{100, -1}, CreepPhase{100, 0}, CreepPhase{100, 1}),
                         [](const ::testing::TestParamInfo<CreepPhase>& i) {
                           const std::int64_t o = i.param.offset_ns;
                           return "At" + std::to_string(i.param.vs) + (o < 0 ? "Minus" : "Plus") +
                                  std::to_string(o < 0 ? -o : o) + "ns";
                         });

// ---- Homing with both overtravel limits wired ------------------------------------------------
// smd23e manual (seeds/003_7a93cebfafae55cd.txt):
//   :1365 hitting the limit of the opposite direction while homing is an Immediate Stop with a
//         "Home Invalid" error -- the status bit is Input Error (:2836);
//   :1367 "The SMD23E will stop with an error if both overtravel limits are activated while the
//         unit is trying to find the home position";
//   :1335 Home already active: the profile starts at step 5 (reverse search);
//   :1382 the search-direction limit already active: the profile starts at step 4 (reverse).
// A limit is judged on its level whenever a run sets off, not only on its edge.
class Smd23eHomingLimits : public Smd23eBench {
protected:
  // Input 1 Home (110), input 2 CW limit (001), input 3 CCW limit (010).
  static constexpr std::uint16_t kHomeAndBothLimits = 0b010'001'110;
  void SetUp() override { configure(ConfigWords{.control = kHomeAndBothLimits}); }
  TestLine& limit(int dir) { return dir > 0 ? in2 : in3; }
  void expect_home_invalid() {
    EXPECT_TRUE(bit1(sw1::kStopped));
    EXPECT_TRUE(bit1(sw1::kInputError));
    EXPECT_TRUE(bit1(sw1::kPositionInvalid));
    EXPECT_FALSE(bit1(sw1::kHomed));
    EXPECT_FALSE(dut.moving());
  }
  // The Profile A timings of Smd23eHoming.ProfileAHomeInputOnly: search stop, 2 s pause, reverse.
  static constexpr double kReverseAt = 0.1 + 940.0 / 1100.0 + 0.1 + 2.0;
};

TEST_F(Smd23eHomingLimits, BothLimitsActiveWhenFindHomeArrivesStopsWithAnError) {
  // Every requested direction and Home level: nothing moves, Input Error (:1367).
  for (const std::uint16_t bit : {msw::kHomeCw, msw::kHomeCcw}) {
    for (const Level home : {Level::Low, Level::High}) {
      configure(ConfigWords{.control = kHomeAndBothLimits});
      command(msw::kResetErrors);
      in1.set(home);
      in2.set(Level::High);
      in3.set(Level::High);
      const std::size_t runs = dut.runs().size();
      command(bit);
      run_to(sched.now() + 3_s);
      EXPECT_EQ(dut.runs().size(), runs) << bit << " home " << static_cast<int>(home);
      EXPECT_TRUE(bit1(sw1::kInputError)) << bit << " home " << static_cast<int>(home);
      EXPECT_FALSE(bit1(sw1::kHomed));
      in1.set(Level::Low);
      in2.set(Level::Low);
      in3.set(Level::Low);
    }
  }
}

TEST_F(Smd23eHomingLimits, OppositeLimitActiveWhenTheReverseSearchStartsAtOnce) {
  // Home already active (:1335): the first run is the reverse search, toward the opposite
  // limit, which is already active -> refused with Input Error, nothing moves; both directions.
  for (const int dir : {+1, -1}) {
    configure(ConfigWords{.control = kHomeAndBothLimits});
    command(msw::kResetErrors);
    in1.set(Level::High);
    limit(-dir).set(Level::High);
    const std::size_t runs = dut.runs().size();
    command(dir > 0 ? msw::kHomeCw : msw::kHomeCcw);
    run_to(sched.now() + 3_s);
    EXPECT_EQ(dut.runs().size(), runs) << dir;
    EXPECT_TRUE(bit1(sw1::kInputError)) << dir;
    EXPECT_FALSE(bit1(sw1::kHomed)) << dir;
    in1.set(Level::Low);
    limit(-dir).set(Level::Low);
  }
}

TEST_F(Smd23eHomingLimits, OppositeLimitAloneDoesNotBlockASearchAwayFromIt) {
  // Sitting on the CCW limit, +Find Home searches CW (away from it): it starts, no error.
  in3.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

TEST_F(Smd23eHomingLimits, OppositeLimitStillActiveWhenTheReverseSearchStartsAfterThePause) {
  // +Find Home from the CCW limit (still active, no edge ever comes): Home at 1000 stops the
  // search; after the 2 s pause the reverse search would set off toward the active CCW limit.
  // Judged on the level: the unit stops with the error at the pause end, no CCW run.
  in3.set(Level::High);
  command(msw::kHomeCw);
  at(when_at(1000), in1, Level::High);
  run_to(Nanos::from_seconds(kReverseAt) - 1_us);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_FALSE(bit1(sw1::kInputError)); // only when it would set off
  sched.run_until_idle();
  expect_home_invalid();
  EXPECT_NEAR(sched.now().seconds(), kReverseAt, 1e-6);
  EXPECT_EQ(dut.runs().back().dir, +1); // the CW search was the last run
}

TEST_F(Smd23eHomingLimits, OppositeLimitTurningActiveInThePauseStopsTheReverseSearch) {
  // The same with the CCW limit's edge during the first pause (no motion then): judged when
  // the reverse search sets off.
  command(msw::kHomeCw);
  at(when_at(1000), in1, Level::High);
  at(Nanos::from_seconds(kReverseAt - 1.0), in3, Level::High);
  sched.run_until_idle();
  expect_home_invalid();
  EXPECT_EQ(dut.runs().back().dir, +1);
}

TEST_F(Smd23eHomingLimits, OppositeLimitHitDuringTheReverseSearchIsAnError) {
  // Reverse search (CCW) under way, Home still active, the CCW limit turns active (:1365).
  in1.set(Level::High);
  command(msw::kHomeCw); // starts at step 5, CCW
  ASSERT_TRUE(bit1(sw1::kMovingCcw));
  at(500_ms, in3, Level::High);
  run_to(600_ms);
  expect_home_invalid();
}

TEST_F(Smd23eHomingLimits, ProfileCWithOnlyTheSearchLimitActiveAtTheCommandReverses) {
  // The neighbour of the error cases: the CW limit alone at the command -> step 4, the reverse
  // search, no error (:1382).
  in2.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

TEST_F(Smd23eHomingLimits, ProfileCWithOnlyTheSearchLimitHitWhileSearchingReverses) {
  // The CW limit alone hit while searching: immediate stop, 2 s pause, reverse, no error
  // (:1365, steps 3-4).
  command(msw::kHomeCw);
  at(500_ms, in2, Level::High);
  run_to(2500_ms + 200_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

TEST_F(Smd23eHomingLimits, BothLimitsActiveDuringTheSearchStopAtOnceInsteadOfReversing) {
  // Started on the CCW limit (still active), searching CW; the CW limit turns active: both are
  // active -> stop with the error (:1367), not the Profile C reversal.
  in3.set(Level::High);
  command(msw::kHomeCw);
  at(500_ms, in2, Level::High);
  run_to(500_ms);
  expect_home_invalid();
  sched.run_until_idle();
  EXPECT_FALSE(dut.moving());
  EXPECT_EQ(dut.runs().back().dir, +1);
}

TEST_F(Smd23eHomingLimits, BothLimitsActiveDuringThePauseEndTheHomingAtOnce) {
  // Profile C: the CW limit stops the search at 500 ms (pause until 2.5 s); the CCW limit
  // turns active at 1.5 s, in the pause: both active -> the error then, the pause ends.
  command(msw::kHomeCw);
  at(500_ms, in2, Level::High);
  at(1500_ms, in3, Level::High);
  run_to(1499_ms);
  EXPECT_FALSE(bit1(sw1::kInputError));
  run_to(1500_ms);
  expect_home_invalid();
  run_to(4_s);
  EXPECT_EQ(dut.runs().back().dir, +1); // no reverse search after the pause
}

TEST_F(Smd23eHomingLimits, SearchLimitStillActiveWhenTheCreepStartsIsAnError) {
  // Profile C with a long CW limit cam that is still active when the creep (step 7) would set
  // off CW toward it: the run is judged on the level -> error, no creep.
  command(msw::kHomeCw);
  at(500_ms, in2, Level::High); // search stops at 500, pause, reverse CCW from 2.5 s
  run_to(2600_ms);
  ASSERT_TRUE(bit1(sw1::kMovingCcw));
  in1.set(Level::High);
  at(2700_ms, in1, Level::Low); // leaving Home: decelerate, second pause, then creep CW
  sched.run_until_idle();
  expect_home_invalid();
  EXPECT_EQ(dut.runs().back().dir, -1); // the reverse search was the last run
}

TEST_F(Smd23eHomingLimits, CcwFindHomeMirrorsTheLevelRules) {
  // -Find Home from the CW limit (the opposite one for CCW) with Home at -1000: the reverse
  // search would set off CW toward the still active CW limit -> error at the pause end.
  in2.set(Level::High);
  command(msw::kHomeCcw);
  ASSERT_TRUE(bit1(sw1::kMovingCcw));
  at(when_at(-1000), in1, Level::High);
  sched.run_until_idle();
  expect_home_invalid();
  EXPECT_NEAR(sched.now().seconds(), kReverseAt, 1e-6);
}

TEST_F(Smd23eHomingLimits, ProximityProfileWithTheSearchLimitActiveStartsReversed) {
  // [MODEL] The manual describes the step-4 start only without the proximity bit (:1382); a
  // search-direction limit met while searching reverses whatever the profile, so an active one
  // at the command does the same instead of driving into it.
  configure(ConfigWords{.control = kHomeAndBothLimits | ccw::kHomeProximityEnable});
  in2.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

TEST_F(Smd23eHomingLimits, ProximityProfileWithBothLimitsActiveIsAnError) {
  configure(ConfigWords{.control = kHomeAndBothLimits | ccw::kHomeProximityEnable});
  in2.set(Level::High);
  in3.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_FALSE(dut.moving());
  EXPECT_TRUE(bit1(sw1::kInputError));
}

class Smd23eHomingIgnoredLimit : public Smd23eBench {
protected:
  Smd23eHomingIgnoredLimit() : Smd23eBench(Params{.fault = Fault::IgnoredLimit}) {}
};

TEST_F(Smd23eHomingIgnoredLimit, TheIgnoredLimitVariantDrivesOnWithBothLimitsActive) {
  // The fault variant a campaign must catch: limits have no effect, so it searches anyway.
  configure(ConfigWords{.control = 0b010'001'110});
  in2.set(Level::High);
  in3.set(Level::High);
  command(msw::kHomeCw);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

// Only repeated relative moves or jogs go past ±8,388,607 (L876), up to the register's
// 32,767,999 (L2910). [MODEL] (README): past it the register reads 32,767,999 while the count
// goes on, and follows the count again once it is back in range.
TEST_F(Smd23eMoves, TheMotorPositionRegisterReadsItsEndWhileTheCountIsPastIt) {
  configure();
  preset(8'388'607);
  const auto relative = [this](std::int32_t offset) {
    command(msw::kRelative, kDrive,
            MoveWords{.value = offset, .vp = 2'999'999, .accel = 5000, .decel = 5000});
    run_to(sched.now() + 10_s);
    ASSERT_TRUE(bit1(sw1::kMoveComplete));
  };
  relative(8'388'607);
  relative(8'388'607);
  EXPECT_EQ(position_word(), 25'165'821); // in range: exact
  relative(8'388'607);                    // the count is at 33,554,428
  EXPECT_EQ(position_word(), 32'767'999);
  const std::int64_t steps = dut.step_position(sched.now());
  relative(-786'428); // count 32,768,000: one beyond the end
  EXPECT_EQ(dut.step_position(sched.now()), steps - 786'428);
  EXPECT_EQ(position_word(), 32'767'999);
  relative(-1); // at the end
  EXPECT_EQ(position_word(), 32'767'999);
  relative(-1); // one inside
  EXPECT_EQ(position_word(), 32'767'998);
}

} // namespace
} // namespace hilrig::models::smd23e::test
