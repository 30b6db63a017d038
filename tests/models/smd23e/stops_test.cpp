// Stops, limits, E-Stop, stall, driver faults and invalid commands with their error bits
// (spec §3.4, §3.7, §4, §6.7).
#include <array>
#include <string>
#include <utility>

#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

using Smd23eStops = Smd23eBench;

// Inputs: 1 = CW limit (001), 2 = CCW limit (010), 3 = E-Stop (101); all active on current.
constexpr std::uint16_t kLimitsAndEStop = 0b101'010'001;

TEST_F(Smd23eStops, ImmediateStopDuringAMoveInvalidatesThePosition) {
  configure();
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  command(msw::kImmediateStop);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 500);
  run_to(2_s);
  EXPECT_EQ(position_word(), 500); // no deceleration: the step train stopped at once
}

TEST_F(Smd23eStops, ImmediateStopWhileIdleKeepsThePositionValid) {
  configure();
  preset(0);
  command(msw::kImmediateStop);
  EXPECT_FALSE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kCommandError));
}

TEST_F(Smd23eStops, EStopStopsAtOnceAndBlocksMovesWhileActive) {
  configure(ConfigWords{.control = kLimitsAndEStop});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = -1000});
  at(300_ms, in3, Level::High);
  run_to(1_s);
  EXPECT_EQ(position_word(), -(60 + 220)); // 0.1 s ramp + 0.2 s at 1100
  EXPECT_TRUE(bit1(sw1::kInputError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_TRUE(bit2(sw2::kDriverEnabled)); // the motor stays powered
  command(msw::kResetErrors);
  command(msw::kJogCw); // refused while E-Stop is active
  run_to(2_s);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kInputError));
  in3.set(Level::Low);
  command(msw::kResetErrors);
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(3_s);
  EXPECT_EQ(position_word(), -180);
}

// An E-Stop is an immediate stop (L976–980, L593): the step train stops at the edge. A step is
// issued only if it was due at or before the edge, to the ns: an edge 1 or 2 ns before a step
// is due leaves that step out, one at or after it keeps it (the tie: the step first). The jog
// runs at v_p = v_s (no ramp, §3.7), started at 10 ms: step k is due at 10 ms + k / v_s.
struct EStopPhase {
  std::int32_t vs; // steps/s
  std::int64_t offset_ns;
};

class Smd23eEStopPhase : public Smd23eBench, public ::testing::WithParamInterface<EStopPhase> {};

TEST_P(Smd23eEStopPhase, AStepIsIssuedOnlyIfDueAtOrBeforeTheEdge) {
  const EStopPhase c = GetParam();
  configure(ConfigWords{.control = kLimitsAndEStop, .vs = c.vs});
  preset(0);
  run_to(10_ms);
  command(msw::kJogCw, kDrive, MoveWords{.vp = c.vs, .accel = 100, .decel = 100});
  constexpr std::int64_t kStep = 3;
  constexpr std::int64_t kSecond = 1'000'000'000; // ns
  const Nanos due = 10_ms + Nanos{kStep * kSecond / c.vs};
  at(due + Nanos{c.offset_ns}, in3, Level::High);
  run_to(due + Nanos{3 * kSecond / c.vs});
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(dut.step_position(sched.now()), c.offset_ns < 0 ? kStep - 1 : kStep);
  EXPECT_EQ(position_word(), c.offset_ns < 0 ? kStep - 1 : kStep);
}

INSTANTIATE_TEST_SUITE_P(Phases, Smd23eEStopPhase,
                         ::testing::Values(EStopPhase{1000, -2}, EStopPhase{1000, -1}, EStopPhase{1000, 0},
                                           EStopPhase{1000, 1}, EStopPhase{100, -11}, EStopPhase{100, -10},
                                           EStopPhase{100, -2}, EStopPhase{100, -1}, EStopPhase{100, 0},
                                           EStopPhase{100, 1}, EStopPhase{1, -1000}, EStopPhase{1, -2},
                                           EStopPhase{1, -1}, EStopPhase{1, 0}, EStopPhase{1, 1}),
                         [](const ::testing::TestParamInfo<EStopPhase>& i) {
                           const std::int64_t o = i.param.offset_ns;
                           return "At" + std::to_string(i.param.vs) + (o < 0 ? "Minus" : "Plus") +
                                  std::to_string(o < 0 ? -o : o) + "ns";
                         });

TEST_F(Smd23eStops, EStopWhileIdleSetsInputError) {
  configure(ConfigWords{.control = kLimitsAndEStop});
  in3.set(Level::High);
  EXPECT_TRUE(bit1(sw1::kInputError));
}

TEST_F(Smd23eStops, LimitInTheDirectionOfTravelLocksThatDirection) {
  configure(ConfigWords{.control = kLimitsAndEStop});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  at(500_ms, in1, Level::High);
  run_to(600_ms);
  EXPECT_EQ(position_word(), 500);
  EXPECT_TRUE(bit1(sw1::kInputError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_TRUE(bit2(sw2::kLimitCondition));
  in1.set(Level::Low);
  EXPECT_FALSE(bit2(sw2::kLimitCondition));                 // cleared when the limit goes inactive
  command(msw::kRelative, kDrive, MoveWords{.value = 100}); // CW still locked out
  run_to(1_s);
  EXPECT_EQ(position_word(), 500);
  command(msw::kRelative, kDrive, MoveWords{.value = -100}); // away from it: allowed
  run_to(2_s);
  EXPECT_EQ(position_word(), 400);
  command(msw::kResetErrors);
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(3_s);
  EXPECT_EQ(position_word(), 500);
}

TEST_F(Smd23eStops, OppositeLimitStopsANonJogMoveWithoutLockout) {
  configure(ConfigWords{.control = kLimitsAndEStop});
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  at(500_ms, in2, Level::High); // CCW limit while moving CW
  run_to(600_ms);
  EXPECT_EQ(position_word(), 500);
  EXPECT_TRUE(bit1(sw1::kInputError));
  in2.set(Level::Low);
  command(msw::kRelative, kDrive, MoveWords{.value = 100}); // no reset needed
  run_to(2_s);
  EXPECT_EQ(position_word(), 600);
}

TEST_F(Smd23eStops, JogIgnoresTheOppositeLimitAndRefusesAnActiveOne) {
  configure(ConfigWords{.control = kLimitsAndEStop});
  in1.set(Level::High); // CW limit active
  command(msw::kJogCw);
  EXPECT_TRUE(bit1(sw1::kInputError)); // starting toward an active limit (L1043)
  EXPECT_TRUE(bit1(sw1::kStopped));
  command(msw::kResetErrors);
  command(msw::kJogCcw); // jogging off the limit
  run_to(500_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCcw));
  EXPECT_FALSE(bit1(sw1::kInputError));
  in2.set(Level::High); // the limit ahead stops it
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit1(sw1::kInputError));
}

TEST_F(Smd23eStops, StallStopsTheMoveAndInvalidatesThePosition) {
  configure(ConfigWords{.control = ccw::kEncoderEnable | ccw::kStallEnable});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  dut.block_shaft(true);
  // Threshold 16 counts = 32 steps at 2048 steps/turn; detected on the 33rd step.
  run_to(600_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_TRUE(bit2(sw2::kStall));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_EQ(position_word(), 533);
  EXPECT_EQ(dut.shaft_steps(sched.now()), 500);
  command(msw::kResetErrors);
  EXPECT_FALSE(bit2(sw2::kStall));
}

// L1255: "the SMD23E/E monitors the encoder inputs for changes while a move is in progress.
// If the encoder inputs do not change as expected, the move stops" (Stall, SW2 bit 14,
// L2885; Position Invalid, L2852). Each move is watched on its own: what an earlier stall left
// between steps and counts is no disagreement of the next move. The encoder here is a pair of
// quadrature lines the test turns (a rig plant's ENC_A/ENC_B, connect_encoder); 2048
// steps/turn and 1024 counts/turn: a count every 2 steps; the threshold 16 counts = 32 steps.
class Smd23eStallWatch : public Smd23eBench {
protected:
  Smd23eStallWatch() { dut.connect_encoder(enc_a, enc_b); }

  // One count forward: (A, B) 00 → 10 → 11 → 01 → 00 (signals/quadrature_decoder.hpp).
  void count_up() {
    static constexpr std::array<std::pair<Level, Level>, 4> kGray{{{Level::High, Level::Low},
                                                                   {Level::High, Level::High},
                                                                   {Level::Low, Level::High},
                                                                   {Level::Low, Level::Low}}};
    const auto [a, b] = kGray[phase_++ % 4];
    if (a != enc_a.level()) enc_a.set(a);
    if (b != enc_b.level()) enc_b.set(b);
  }
  // Plays the move as the rig does: at each step the encoder turns (a count every second
  // step of this move, up to `turns` steps), then the board compares (Smd23eDut::follow).
  // Returns the steps the move made.
  std::int64_t play(std::int64_t turns) {
    const std::int64_t origin = dut.runs().back().origin;
    for (std::int64_t k = 1; dut.moving(); ++k) {
      run_to(when_at(origin + k)); // the last step's time is the move's end
      if (k <= turns && k % 2 == 0) count_up();
      dut.watch_encoder();
    }
    return dut.step_position(sched.now()) - origin;
  }

  TestLine enc_a{sched};
  TestLine enc_b{sched};
  std::size_t phase_ = 0;
};

TEST_F(Smd23eStallWatch, AfterAStallResetAndPresetsTheNextMoveIsWatchedOnItsOwn) {
  configure(ConfigWords{.control = ccw::kEncoderEnable | ccw::kStallEnable});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  // The load does not turn: 17 counts behind (> 16) at step 34.
  EXPECT_EQ(play(0), 34);
  ASSERT_TRUE(bit2(sw2::kStall));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  command(msw::kResetErrors);
  preset(0);
  command(msw::kPresetEncoder, kDrive, MoveWords{.value = 0});
  EXPECT_FALSE(bit2(sw2::kStall));
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  EXPECT_EQ(play(1000), 1000); // it follows: no stall, though 17 counts are still missing
  EXPECT_FALSE(bit2(sw2::kStall));
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 1000);
  EXPECT_EQ(encoder_word(), 500);
}

TEST_F(Smd23eStallWatch, ASecondRealStallAfterResetIsStillDetected) {
  configure(ConfigWords{.control = ccw::kEncoderEnable | ccw::kStallEnable});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  ASSERT_EQ(play(0), 34);
  command(msw::kResetErrors);
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  // The load follows 100 steps (50 counts), then sticks: 17 counts behind at step 134.
  EXPECT_EQ(play(100), 134);
  EXPECT_TRUE(bit2(sw2::kStall));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(position_word(), 134);
}

TEST_F(Smd23eStops, ABlockedShaftStallsEachMoveAfterTheThreshold) {
  configure(ConfigWords{.control = ccw::kEncoderEnable | ccw::kStallEnable});
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  dut.block_shaft(true); // detected on the 33rd step after the block (see above)
  run_to(600_ms);
  ASSERT_EQ(position_word(), 533);
  dut.block_shaft(false);
  command(msw::kResetErrors);
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // the shaft turns: no stall
  run_to(2_s);
  EXPECT_EQ(position_word(), 1000);
  EXPECT_FALSE(bit2(sw2::kStall));
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(2500_ms);
  dut.block_shaft(true); // blocked again: 33 steps more, not at once for the old 33
  run_to(2600_ms);
  EXPECT_TRUE(bit2(sw2::kStall));
  EXPECT_EQ(position_word(), 1000 + 500 + 33);
  command(msw::kResetErrors);
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // still blocked: this move's 33
  run_to(4_s);
  EXPECT_TRUE(bit2(sw2::kStall));
  EXPECT_EQ(position_word(), 33);
}

TEST_F(Smd23eStops, M15ResetDriverFault) {
  configure();
  dut.over_temperature();
  EXPECT_TRUE(bit2(sw2::kDriverFault));
  write(0, 0x0400);
  write(msw::kResetErrors, 0x0400); // Reset Errors + Clear Driver Fault, DriveEn = 0
  EXPECT_FALSE(bit2(sw2::kDriverFault));
  EXPECT_FALSE(bit2(sw2::kDriverEnabled));
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.0);
  write(0, 0x8000);
  EXPECT_TRUE(bit2(sw2::kDriverEnabled));
}

TEST_F(Smd23eStops, DriverFaultIsNotClearedWhileTheDriverIsEnabled) {
  configure();
  dut.over_temperature();
  command(msw::kResetErrors, kDrive | lsw::kClearDriverFault);
  EXPECT_TRUE(bit2(sw2::kDriverFault));
}

// smd23e manual (seeds/003_7a93cebfafae55cd.txt:565): over temperature removes power from the
// motor; :2892: SW2 bit 7 Driver Fault is 1 during the fault while the driver is enabled;
// :2922: "Once you have cleared the fault condition, you can reset the Driver Fault".
TEST_F(Smd23eStops, OverTemperatureStopsAJogAndIsResetOnlyOnceCooled) {
  configure();
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  ASSERT_TRUE(dut.moving());
  dut.set_over_temperature(true);
  const std::int64_t at_fault = dut.shaft_steps(sched.now());
  run_to(600_ms);
  EXPECT_EQ(dut.shaft_steps(sched.now()), at_fault); // no step after the fault (L565)
  EXPECT_TRUE(bit2(sw2::kDriverFault));
  EXPECT_TRUE(bit2(sw2::kDriverEnabled)); // the global enable bit stays (L2884)
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.0);
  write(0, lsw::kClearDriverFault);
  write(msw::kResetErrors, lsw::kClearDriverFault); // still hot: the fault stays (L2922)
  EXPECT_TRUE(bit2(sw2::kDriverFault));
  dut.set_over_temperature(false);
  write(0, lsw::kClearDriverFault);
  write(msw::kResetErrors, lsw::kClearDriverFault); // cooled: Reset Driver Fault (L2924-2946)
  EXPECT_FALSE(bit2(sw2::kDriverFault));
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.0); // DriveEn was 0 (L2946)
}

// [MODEL] the driver enabled while the unit is still over temperature faults at once
// (L2892: the bit is 1 during the fault whenever the driver is enabled).
TEST_F(Smd23eStops, DriverEnabledWhileStillHotFaults) {
  configure();
  write(0, 0); // driver disabled
  dut.set_over_temperature(true);
  EXPECT_FALSE(bit2(sw2::kDriverFault)); // not while the driver is disabled (L2892)
  write(0, kDrive);
  EXPECT_TRUE(bit2(sw2::kDriverFault));
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.0);
}

TEST_F(Smd23eStops, NetworkLossStopsAndItsReturnSetsTheErrorBits) {
  configure();
  preset(0);
  command(msw::kJogCw);
  run_to(500_ms);
  dut.network_link(false); // [A] motion stops at once on link loss
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word(), 500);
  dut.network_link(true); // L2849, L2893
  EXPECT_TRUE(bit2(sw2::kNetworkLost));
  EXPECT_TRUE(bit1(sw1::kInputError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  command(msw::kResetErrors);
  EXPECT_FALSE(bit2(sw2::kNetworkLost));
  EXPECT_FALSE(bit1(sw1::kInputError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid)); // only a preset or homing validates it
}

TEST_F(Smd23eStops, TemperatureWarningIsReported) {
  configure();
  dut.set_temperature_warning(true);
  EXPECT_TRUE(bit2(sw2::kTempWarning));
  dut.set_temperature_warning(false);
  EXPECT_FALSE(bit2(sw2::kTempWarning));
}

TEST_F(Smd23eStops, StartIndexedInputCapturesTheEncoderOnEveryTransition) {
  configure(ConfigWords{.control = 0b011 | ccw::kEncoderEnable});
  command(msw::kJogCw);
  at(500_ms, in1, Level::High); // step 500 = 250 counts
  at(700_ms, in1, Level::Low);  // step 720 = 360 counts
  run_to(600_ms);
  EXPECT_EQ(captured_word(), 250);
  run_to(800_ms);
  EXPECT_EQ(captured_word(), 360);
}

using Smd23eInvalid = Smd23eBench;

TEST_F(Smd23eInvalid, OutOfRangeMoveParametersSetCommandErrorWithoutMotion) {
  configure();
  const auto refused = [this](MoveWords m) {
    command(msw::kResetErrors);
    command(msw::kRelative, kDrive, m);
    run_to(sched.now() + 1_s);
    return bit1(sw1::kCommandError) && !bit1(sw1::kMoveComplete) && dut.step_position(sched.now()) == 0;
  };
  EXPECT_TRUE(refused({.value = 8'388'608}));     // (8388, 608): beyond ±8,388,607
  EXPECT_TRUE(refused({.value = 100, .vp = 99})); // below v_s
  EXPECT_TRUE(refused({.value = 100, .vp = 3'000'000}));
  EXPECT_TRUE(refused({.value = 100, .accel = 0}));
  EXPECT_TRUE(refused({.value = 100, .decel = 5001}));
  EXPECT_TRUE(refused({.value = 100, .word9 = 5001})); // jerk
}

TEST_F(Smd23eInvalid, MixedSignMultiWordIsRejected) {
  configure();
  Words w = block(msw::kRelative, kDrive, MoveWords{.value = 1000});
  w[3] = as_word(-5); // (1, −5)
  dut.write_outputs(block(0, kDrive));
  dut.write_outputs(w);
  EXPECT_TRUE(bit1(sw1::kCommandError));
}

TEST_F(Smd23eInvalid, OutOfRangeJogSetsCommandErrorAndMoveComplete) {
  configure();
  command(msw::kJogCw, kDrive, MoveWords{.accel = 0});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kMoveComplete)); // L2860
  EXPECT_TRUE(bit1(sw1::kStopped));
}

// Move Complete around a refused command, after a good move set it (L2860): it "is reset to
// '0' when the next move command is written", refused or not; it "is also set along with the
// Command Error bit ... when any Jog Move or Registration Move parameters are outside of their
// valid ranges", and "is not set on a command error for any other type of command". The move
// commands are the moves L2860 lists (Absolute, Relative, Jog, Registration, Assembled) and
// Find Home (L887 counts the homing operations among the move commands). Preset Position is
// not a move: its refusal leaves Move Complete as it was (only a preset done resets it, L2860).
TEST_F(Smd23eInvalid, RefusedMoveCommandsResetMoveCompleteExceptJogAndRegistration) {
  configure();
  struct Refused {
    const char* what;
    std::uint16_t msw;
    std::uint16_t lsw;
    MoveWords words;
    bool move_complete;
  };
  const Refused cases[] = {
      {"absolute, target beyond +-8,388,607", msw::kAbsolute, kDrive, {.value = 8'388'608}, false},
      {"relative, acceleration 0", msw::kRelative, kDrive, {.value = 100, .accel = 0}, false},
      {"jog, acceleration 0", msw::kJogCw, kDrive, {.accel = 0}, true},
      {"registration, stopping distance < 0", msw::kJogCw, kDrive | lsw::kRegistration, {.value = -1}, true},
      {"find home, no Home input", msw::kHomeCw, kDrive, {}, false},
      {"run assembled, nothing programmed", msw::kRunAssembled, kDrive, {}, false},
      {"preset position beyond +-8,388,607", msw::kPresetPosition, kDrive, {.value = 8'388'608}, true},
  };
  for (const Refused& c : cases) {
    command(msw::kResetErrors);
    command(msw::kRelative, kDrive, MoveWords{.value = 100});
    run_to(sched.now() + 1_s);
    ASSERT_TRUE(bit1(sw1::kMoveComplete)) << c.what;
    ASSERT_FALSE(bit1(sw1::kCommandError)) << c.what;
    command(c.msw, c.lsw, c.words);
    EXPECT_TRUE(bit1(sw1::kCommandError)) << c.what;
    EXPECT_EQ(bit1(sw1::kMoveComplete), c.move_complete) << c.what;
    EXPECT_TRUE(bit1(sw1::kStopped)) << c.what;
  }
}

TEST_F(Smd23eInvalid, SeveralCommandBitsAtOnce) {
  configure();
  command(msw::kRelative | msw::kJogCw, kDrive, MoveWords{.value = 100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kStopped));
}

TEST_F(Smd23eInvalid, ResetErrorsWithAMoveRunsTheMove) {
  configure();
  command(msw::kJogCw, kDrive, MoveWords{.accel = 0});
  command(msw::kResetErrors | msw::kRelative, kDrive, MoveWords{.value = 100});
  EXPECT_FALSE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kMovingCw));
}

TEST_F(Smd23eInvalid, ReservedCommandWordBits) {
  configure();
  command(msw::kRelative, kDrive | 0x0040, MoveWords{.value = 100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kStopped));
}

TEST_F(Smd23eInvalid, NewMoveWhileMovingIsRefused) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(500_ms);
  command(msw::kRelative, kDrive, MoveWords{.value = 50});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  run_to(2_s);
  EXPECT_EQ(position_word(), 1000);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eInvalid, ResumeWithNothingHeld) {
  configure();
  command(msw::kResume);
  EXPECT_TRUE(bit1(sw1::kCommandError));
}

TEST_F(Smd23eInvalid, MovesNeedTheDriverEnabled) {
  configure();
  command(msw::kRelative, 0, MoveWords{.value = 100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  EXPECT_TRUE(bit1(sw1::kStopped));
}

class Smd23eNoEncoder : public Smd23eBench {
protected:
  Smd23eNoEncoder() : Smd23eBench(Params{.has_encoder = false}) {}
};

TEST_F(Smd23eNoEncoder, EncoderCommandsAreCommandErrors) {
  configure();
  command(msw::kRelative, kDrive | lsw::kEncoderMove, MoveWords{.value = 100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  command(msw::kResetErrors);
  command(msw::kPresetEncoder, kDrive, MoveWords{.value = 100});
  EXPECT_TRUE(bit1(sw1::kCommandError));
  // And the encoder cannot be enabled in the configuration.
  dut.write_outputs(config_block(ConfigWords{.control = ccw::kEncoderEnable}));
  EXPECT_NE(dut.input_words()[0] & sw1::kConfigError, 0);
}

} // namespace
} // namespace hilrig::models::smd23e::test
