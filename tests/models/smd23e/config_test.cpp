// Power-up, Configuration Mode, status words, heartbeat and idle current (spec §6.2–§6.6).
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

using Smd23eConfig = Smd23eBench;

TEST_F(Smd23eConfig, M05UnconfiguredUnitReads0x6408) {
  // Controller OK, Configuration Error, Position Invalid, Axis Stopped; Command Mode.
  EXPECT_EQ(dut.input_words()[0], 0x6408);
  // Move commands are ignored: no motion, no error bit.
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(1_s);
  EXPECT_EQ(dut.input_words()[0], 0x6408);
  EXPECT_EQ(dut.step_position(sched.now()), 0);
}

TEST_F(Smd23eConfig, M06PowerUpInputWordsFollowTheText) {
  // Unconfigured: all inputs NC (active-level bits 0), no current → all three active.
  // The text never sets SW2 bit 13 nor NetLoss at power-up: 0x0007 plus the heartbeat.
  const Words in = dut.input_words();
  EXPECT_EQ(in[1] & ~sw2::kHeartbeat, 0x0007);
  for (std::size_t i = 2; i < kWords; ++i) {
    EXPECT_EQ(in[i], 0) << i;
  }
}

class Smd23eConfigAsFigure : public Smd23eBench {
protected:
  Smd23eConfigAsFigure() : Smd23eBench(Params{.sw2_bit13_as_figure = true, .netloss_at_powerup = true}) {}
};

TEST_F(Smd23eConfigAsFigure, M06TheExampleDumpWithTheFigureSwitches) {
  // Bytes 08 64 47 28: W0 = 0x6408, W1 = 0x2847 with the heartbeat high (500 ms … 1 s).
  run_to(750_ms);
  const Words in = dut.input_words();
  EXPECT_EQ(in[0], 0x6408);
  EXPECT_EQ(in[1], 0x2847);
}

TEST_F(Smd23eConfig, ValidConfigurationIsMirroredAndClearsConfigurationError) {
  const Words w = config_block(ConfigWords{});
  dut.write_outputs(w);
  const Words in = dut.input_words();
  EXPECT_EQ(in[0], w[0]); // a copy of the written control word
  for (std::size_t i : {1U, 2U, 3U, 4U, 6U, 7U, 8U}) {
    EXPECT_EQ(in[i], w[i]) << i;
  }
  EXPECT_EQ(in[5], 0);
  EXPECT_EQ(in[9], 0);
  dut.write_outputs(Words{0, kDrive});
  // Command Mode: CtrlOK, Position Invalid (a configuration was written), Stopped.
  EXPECT_EQ(sw1(), sw1::kControllerOk | sw1::kPositionInvalid | sw1::kStopped);
  EXPECT_TRUE(bit2(sw2::kDriverEnabled));
}

TEST_F(Smd23eConfig, M18MotorCurrentEncoding) {
  for (int c : {10, 25, 34}) {
    const auto current = static_cast<std::uint16_t>(c);
    dut.write_outputs(config_block(ConfigWords{.current10 = current}));
    EXPECT_EQ(dut.input_words()[0] & sw1::kConfigError, 0) << current;
    dut.write_outputs(Words{0, kDrive});
    EXPECT_EQ(dut.input_words()[8], current); // 1.0, 2.5, 3.4 Arms while not idle
    EXPECT_DOUBLE_EQ(dut.motor_current_amps(), current / 10.0);
  }
  for (int c : {35, 9}) {
    const auto current = static_cast<std::uint16_t>(c);
    dut.write_outputs(config_block(ConfigWords{.current10 = current}));
    EXPECT_NE(dut.input_words()[0] & sw1::kConfigError, 0) << current;
  }
}

TEST_F(Smd23eConfig, M25StartingSpeedLowerWordAbove999IsInvalid) {
  Words w = config_block(ConfigWords{});
  w[2] = 1;
  w[3] = 1000; // numerically 2000, but the lower word is > 999
  dut.write_outputs(w);
  EXPECT_NE(dut.input_words()[0] & sw1::kConfigError, 0);
}

TEST_F(Smd23eConfig, InvalidConfigurationsSetConfigurationError) {
  const auto invalid = [this](ConfigWords c, Words patch_mask = {}, Words patch = {}) {
    Words w = config_block(c);
    for (std::size_t i = 0; i < kWords; ++i) {
      if (patch_mask[i] != 0) {
        w[i] = patch[i];
      }
    }
    dut.write_outputs(w);
    // Status Word 1's flag: a mirrored control word may itself have bit 13 (stall enable).
    return (dut.status1() & sw1::kConfigError) != 0;
  };
  EXPECT_TRUE(invalid({.control = 1U << 12}));          // reserved bit
  EXPECT_TRUE(invalid({.word = 0x8000 | (1U << 5)}));   // reserved bit
  EXPECT_TRUE(invalid({.control = 0b001'001}));         // two CW limits
  EXPECT_TRUE(invalid({.control = 0b111}));             // code 111
  EXPECT_TRUE(invalid({.control = ccw::kStallEnable})); // stall without encoder
  EXPECT_TRUE(invalid({.steps_per_turn = 199}));
  EXPECT_TRUE(invalid({.idle_percent = 101}));
  EXPECT_TRUE(invalid({.vs = 0}));
  EXPECT_TRUE(invalid({.vs = 2'000'000}));
  EXPECT_TRUE(invalid({}, Words{0, 0, 0, 0, 0, 0, 1}, Words{0, 0, 0, 0, 0, 0, 1000})); // 1024 pulses only
  EXPECT_FALSE(invalid({.control = 0})); // three general-purpose inputs
  EXPECT_FALSE(invalid({.control = 0b110'010'001 | ccw::kEncoderEnable | ccw::kStallEnable}));
}

// Manual L2403: a command runs on a 0→1 transition of its bit; L2405: "If a bit is set in the
// Control Word (Word 0) while in Configuration Mode and you switch to Command Mode with the
// same bit set, the command will not occur because the bit must transition between writes".
// The edge is judged against the Control Word last written, whatever the mode.
TEST_F(Smd23eConfig, CommandBitsHeldSetThroughTheSwitchToCommandModeDoNotTrigger) {
  // Control Word 0x8002: input 1 as CCW Limit (code 010, L2308) puts bit 1 (Relative) at 1.
  dut.write_outputs(config_block(ConfigWords{.control = 0b010}));
  write(msw::kRelative, kDrive, MoveWords{.value = 100}); // bit 1 still set: no transition
  run_to(1_s);
  EXPECT_EQ(dut.step_position(sched.now()), 0);
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  command(msw::kRelative, kDrive, MoveWords{.value = 100}); // cleared, then set: it runs
  run_to(2_s);
  EXPECT_EQ(dut.step_position(sched.now()), 100);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eConfig, ResetErrorsHeldThroughTheSwitchAsTheEncoderEnableBitDoesNotTrigger) {
  configure();
  command(msw::kAbsolute, kDrive, MoveWords{.value = 100}); // Position Invalid: refused (L2854)
  ASSERT_TRUE(bit1(sw1::kCommandError));
  // Control Word bit 10 is Encoder Enable in Configuration Mode (L2286) and Reset Errors in
  // Command Mode (L2439): 0x8400 followed by 0x0400 holds bit 10 through the switch.
  dut.write_outputs(config_block(ConfigWords{.control = ccw::kEncoderEnable}));
  write(msw::kResetErrors);
  EXPECT_TRUE(bit1(sw1::kCommandError));
  command(msw::kResetErrors);
  EXPECT_FALSE(bit1(sw1::kCommandError));
}

// The auditor's words (Modbus 1024..1033): configuration 8000 8000 0000 0064 0800 0000 0400
// 0032 0014 0000 (Control Word bit 1 = 0), then in one write 0002 8000 0001 0000 0001 0000
// 0064 0064 0000 0000: bit 1 went 0→1 across the switch, so the Relative move of +1000 runs
// (L2403), at v_p 1000, A = D = 100.
TEST_F(Smd23eConfig, ACommandBitThatRisesAcrossTheSwitchToCommandModeRuns) {
  dut.write_outputs(config_block(ConfigWords{.word = 0x8000}));
  write(msw::kRelative, kDrive, MoveWords{.value = 1000, .vp = 1000, .accel = 100, .decel = 100});
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  run_to(2_s); // 1000 steps at up to 1000 steps/s: 1.009 s
  EXPECT_EQ(position_word(), 1000);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_FALSE(bit1(sw1::kCommandError));
}

TEST_F(Smd23eConfig, PresetPositionAndResetErrorsRiseAcrossTheSwitchToo) {
  dut.write_outputs(config_block(ConfigWords{}));
  write(msw::kPresetPosition, kDrive, MoveWords{.value = 5}); // 0x0200 after 0x8000 (L2403)
  EXPECT_EQ(position_word(), 5);
  EXPECT_FALSE(bit1(sw1::kPositionInvalid));
  command(msw::kResume); // nothing held: a Command Error to reset
  ASSERT_TRUE(bit1(sw1::kCommandError));
  dut.write_outputs(config_block(ConfigWords{}));
  write(msw::kResetErrors); // 0x0400 after 0x8000
  EXPECT_FALSE(bit1(sw1::kCommandError));
}

// L2846: Position Invalid is "1" when "A configuration is written to the SMD23E"; L1132: a
// Blend Move "stays in memory until power is removed, the unit is sent new Configuration
// Data, or a new Blend or Dwell Move is written". Both name the write, not a change: the same
// configuration written again is a configuration written (spec §6.4 [A]: "received in
// Configuration Mode").
class Smd23eRewrite : public Smd23eBench {
protected:
  // Two Blend segments of +1000 steps (§6.5, L1112-L1132), then Preset Position 5
  // (the auditor's 0200 8000 0000 0005): SW1 0x4008, Controller OK and Axis Stopped.
  void blend_and_preset() {
    configure();
    command(msw::kProgramMove);
    for (std::int32_t vp : {1100, 2100}) {
      write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = vp});
      write(msw::kProgramMove, kDrive, MoveWords{.value = 1000, .vp = vp});
    }
    write(0);
    preset(5);
    ASSERT_EQ(sw1(), sw1::kControllerOk | sw1::kStopped);
  }
};

TEST_F(Smd23eRewrite, TheSameConfigurationWrittenAgainInvalidatesThePositionAndErasesTheBlend) {
  blend_and_preset();
  dut.write_outputs(config_block(ConfigWords{})); // the very words configure() wrote
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(sw1(), sw1::kControllerOk | sw1::kPositionInvalid | sw1::kStopped); // 0x4408
  command(msw::kRunAssembled); // nothing in RAM to run: a Command Error [A]
  run_to(5_s);
  EXPECT_EQ(dut.step_position(sched.now()), 0);
  EXPECT_TRUE(bit1(sw1::kCommandError));
}

// [MODEL] the manual does not say what a configuration written during a move does to it; the
// model stops the step train at once, the same words again as for different ones.
TEST_F(Smd23eRewrite, TheSameConfigurationWrittenDuringAMoveStopsItAsAnyOther) {
  configure();
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // 0.1 s ramp (60 steps), then 1100/s
  run_to(500_ms);
  dut.write_outputs(config_block(ConfigWords{}));
  EXPECT_EQ(dut.step_position(sched.now()), 500);
  run_to(2_s);
  EXPECT_EQ(dut.step_position(sched.now()), 500);
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eRewrite, ReadPresentConfigurationWritesNoConfiguration) {
  blend_and_preset();
  // L2329: "You cannot write new configuration data to the unit while this bit is set."
  Words w = config_block(ConfigWords{});
  w[1] = static_cast<std::uint16_t>(w[1] | cfgw::kReadPresent);
  dut.write_outputs(w);
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(sw1(), sw1::kControllerOk | sw1::kStopped); // still valid
  command(msw::kRunAssembled); // the Blend is still there: +2000 (moves_test's timing, 1.63 s)
  run_to(5_s);
  EXPECT_EQ(position_word(), 5 + 2000);
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
}

TEST_F(Smd23eConfig, M17SaveConfigurationReportsSuccessAndStopsAnswering) {
  Words w = config_block(ConfigWords{});
  dut.write_outputs(w);
  w[1] = static_cast<std::uint16_t>(w[1] | cfgw::kSaveConfig);
  dut.write_outputs(w);
  EXPECT_EQ(dut.input_words()[9], 0xAAAA);
  // The unit stops answering commands until power is cycled.
  dut.write_outputs(Words{0, kDrive});
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(1_s);
  EXPECT_EQ(dut.step_position(sched.now()), 0);
}

TEST_F(Smd23eConfig, M17SaveWithInvalidDataIsIgnored) {
  Words w = config_block(ConfigWords{.steps_per_turn = 100});
  dut.write_outputs(w);
  w[1] = static_cast<std::uint16_t>(w[1] | cfgw::kSaveConfig);
  dut.write_outputs(w);
  EXPECT_EQ(dut.input_words()[9], 0);
}

TEST_F(Smd23eConfig, HeartbeatTogglesEvery500msInCommandModeOnly) {
  configure();
  const auto hb = [this](Nanos t) {
    run_to(t);
    return bit2(sw2::kHeartbeat);
  };
  EXPECT_FALSE(hb(250_ms));
  EXPECT_TRUE(hb(750_ms));
  EXPECT_FALSE(hb(1250_ms));
  EXPECT_TRUE(hb(1750_ms));
  dut.write_outputs(config_block(ConfigWords{}));
  EXPECT_EQ(dut.input_words()[1] & sw2::kHeartbeat, 0); // word 1 mirrors the config word
  EXPECT_FALSE(bit2(sw2::kHeartbeat));
}

TEST_F(Smd23eConfig, M12IdleCurrentDropsTo25PercentAfter1500ms) {
  configure(ConfigWords{.idle_percent = 25, .current10 = 20});
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(1499_ms);
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(1500_ms);
  EXPECT_EQ(dut.input_words()[8], 5); // 2.0 A × 25 % = 0.5 A
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.5);
  // Full current again while moving, and for 1.5 s after the move.
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // ends at +1.0 s
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(2500_ms + 1499_ms);
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(2500_ms + 1501_ms);
  EXPECT_EQ(dut.input_words()[8], 5);
}

// smd23e manual (seeds/003_7a93cebfafae55cd.txt:2350): "Changes to the Idle Current only take
// effect at the end of the first move after re-configuration"; :781 the current drops to the
// idle level after 1.5 s without motion; :1265 the percentage is the level it drops *to*.
// 2.0 A motor current: 25 % reads 5, 75 % reads 15 (input word 8 = A x 10).
TEST_F(Smd23eConfig, ReconfiguredIdleCurrentWaitsForTheEndOfTheFirstMove) {
  configure(ConfigWords{.idle_percent = 25, .current10 = 20});
  run_to(1500_ms);
  ASSERT_EQ(dut.input_words()[8], 5);
  configure(ConfigWords{.idle_percent = 75, .current10 = 20}); // at 1.5 s
  run_to(1500_ms + 1499_ms);
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(1500_ms + 1500_ms);
  EXPECT_EQ(dut.input_words()[8], 5); // idle again, still at the old 25 %
  run_to(10_s);
  EXPECT_EQ(dut.input_words()[8], 5);                        // however long it idles
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // 10 s .. 11 s
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(11_s + 1499_ms);
  EXPECT_EQ(dut.input_words()[8], 20);
  run_to(11_s + 1500_ms);
  EXPECT_EQ(dut.input_words()[8], 15); // the end of that move brought in 75 %
}

TEST_F(Smd23eConfig, OnlyTheLastIdleCurrentBeforeTheMoveIsTakenAtItsEnd) {
  configure(ConfigWords{.idle_percent = 25, .current10 = 20});
  configure(ConfigWords{.idle_percent = 100, .current10 = 20});
  configure(ConfigWords{.idle_percent = 0, .current10 = 20});
  run_to(1500_ms);
  EXPECT_EQ(dut.input_words()[8], 5);                        // neither 100 % nor 0 % yet
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // 1.5 s .. 2.5 s
  run_to(2500_ms + 1500_ms);
  EXPECT_EQ(dut.input_words()[8], 0); // 0 %: no holding current (:1261)
  EXPECT_DOUBLE_EQ(dut.motor_current_amps(), 0.0);
}

TEST_F(Smd23eConfig, ReconfigurationThatKeepsTheIdleCurrentKeepsIt) {
  // Sweep the new percentage around the old one: only a changed value waits for a move, and
  // after the move each value is exactly what was configured.
  for (const int percent : {49, 50, 51}) {
    const auto idle = static_cast<std::uint16_t>(percent);
    Scheduler s2;
    Smd23e unit(s2);
    const auto cfg = [&](std::uint16_t pct, std::uint16_t steps) {
      ConfigWords c{.idle_percent = pct, .current10 = 20};
      c.steps_per_turn = steps;
      unit.write_outputs(config_block(c));
      unit.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
    };
    cfg(50, 2048);
    cfg(idle, 4096); // a re-configuration (steps/turn changed too)
    s2.run_until(1500_ms);
    EXPECT_EQ(unit.input_words()[8], 10) << idle; // 50 % of 2.0 A until a move ends
    unit.write_outputs(block(0, kDrive, MoveWords{.value = 1000}));
    unit.write_outputs(block(msw::kRelative, kDrive, MoveWords{.value = 1000}));
    s2.run_until(2500_ms + 1500_ms);
    EXPECT_DOUBLE_EQ(unit.motor_current_amps(), 2.0 * idle / 100.0) << idle;
  }
}

TEST_F(Smd23eConfig, M19TenWordsEachWay) {
  std::array<std::uint16_t, 10> buf{};
  EXPECT_EQ(dut.read_input_registers(0, buf), RegisterStatus::Ok);
  EXPECT_EQ(dut.read_input_registers(1, buf), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(dut.read_holding_registers(1024, buf), RegisterStatus::Ok);
  EXPECT_EQ(dut.read_holding_registers(0, buf), RegisterStatus::Ok); // FC 3 reads input words too
  EXPECT_EQ(dut.write_holding_registers(1024, buf), RegisterStatus::Ok);
  EXPECT_EQ(dut.write_holding_registers(1025, buf), RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(dut.write_holding_registers(0, std::span(buf.data(), 1)), RegisterStatus::IllegalDataAddress);
}

TEST_F(Smd23eConfig, M16CommandCodes) {
  EXPECT_EQ(msw::kAbsolute, 0x0001);
  EXPECT_EQ(msw::kRelative, 0x0002);
  EXPECT_EQ(msw::kHold, 0x0004);
  EXPECT_EQ(msw::kResume, 0x0008);
  EXPECT_EQ(msw::kImmediateStop, 0x0010);
  EXPECT_EQ(msw::kHomeCw, 0x0020);
  EXPECT_EQ(msw::kHomeCcw, 0x0040);
  EXPECT_EQ(msw::kJogCw, 0x0080);
  EXPECT_EQ(msw::kJogCcw, 0x0100);
  EXPECT_EQ(msw::kPresetPosition, 0x0200);
  EXPECT_EQ(msw::kResetErrors, 0x0400);
  EXPECT_EQ(msw::kProgramMove, 0x0800);
  EXPECT_EQ(msw::kProgramMove | msw::kProgramSegment, 0x1800);
  EXPECT_EQ(msw::kRunAssembled, 0x2000);
  EXPECT_EQ(msw::kPresetEncoder, 0x4000);
}

TEST_F(Smd23eConfig, M13InvertedSinkingSensorIsCompensatedByTheActiveLevel) {
  // A sinking sensor with a pull-up: sensor on → no current through the input (Low).
  configure(ConfigWords{.word = 0x8000 | 0x6}); // input 1 NC, inputs 2–3 NO
  in1.set(Level::Low);                          // sensor on
  in2.set(Level::Low);
  EXPECT_TRUE(bit2(sw2::kInput1));  // NC: active with no current — follows the sensor
  EXPECT_FALSE(bit2(sw2::kInput2)); // NO: inverted — inactive while the sensor is on
  in1.set(Level::High);
  EXPECT_FALSE(bit2(sw2::kInput1));
}

// Position Invalid is "1" when "A configuration is written to the SMD23E" (L2846), and an
// invalid one is written too: Configuration Error is "1 ... after any invalid configuration
// has been written to the driver" (L2830). The unit is then unconfigured, does not power the
// motor (L2828) and reads as at power-up, 0x6408 (L2284, L2372); a valid one reads 0x4408.
// Cases: the Starting Speed's range 1 ... 1,999,999 (L863, L2268), at each end and one beyond.
struct WrittenStartingSpeed {
  const char* name;
  std::int32_t vs;
  bool valid;
};

class Smd23eConfigWritten : public Smd23eBench, public ::testing::WithParamInterface<WrittenStartingSpeed> {};

TEST_P(Smd23eConfigWritten, InvalidatesThePositionValidOrNot) {
  configure();
  preset(5);
  ASSERT_EQ(sw1(), sw1::kControllerOk | sw1::kStopped); // 0x4008: a valid position
  dut.write_outputs(config_block(ConfigWords{.vs = GetParam().vs}));
  EXPECT_EQ((sw1() & sw1::kConfigError) != 0, !GetParam().valid);
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(sw1(), GetParam().valid ? 0x4408 : 0x6408);
  EXPECT_EQ(bit2(sw2::kDriverEnabled), GetParam().valid);
  configure(); // a valid configuration and a preset make it valid again (L992)
  preset(5);
  EXPECT_EQ(sw1(), sw1::kControllerOk | sw1::kStopped);
}

// [MODEL] as for a valid one (README): an invalid configuration written during a move stops
// the step train at once, the more so as the unit no longer powers the motor (L2828) nor
// accepts commands (L2239) that could stop it.
TEST_F(Smd23eConfig, AnInvalidConfigurationWrittenDuringAMoveStopsIt) {
  configure();
  preset(0);
  command(msw::kRelative, kDrive, MoveWords{.value = 1000}); // 0.1 s ramp (60 steps), then 1100/s
  run_to(500_ms);
  dut.write_outputs(config_block(ConfigWords{.vs = 0}));
  EXPECT_EQ(dut.step_position(sched.now()), 500);
  run_to(2_s);
  EXPECT_EQ(dut.step_position(sched.now()), 500);
  dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(sw1(), 0x6408); // stopped, no Move Complete (L2860)
}

INSTANTIATE_TEST_SUITE_P(Cases, Smd23eConfigWritten,
                         ::testing::Values(WrittenStartingSpeed{"Zero", 0, false},
                                           WrittenStartingSpeed{"One", 1, true},
                                           WrittenStartingSpeed{"Top", 1'999'999, true},
                                           WrittenStartingSpeed{"AboveTop", 2'000'000, false}),
                         [](const ::testing::TestParamInfo<WrittenStartingSpeed>& i) {
                           return std::string(i.param.name);
                         });

} // namespace
} // namespace hilrig::models::smd23e::test
