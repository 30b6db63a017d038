// The SMD23E's power cycle (power_off / power_on): what flash keeps and what RAM loses, from its
// manual (seeds/003_7a93cebfafae55cd.txt).

#include "smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

class Smd23ePowerCycle : public Smd23eBench {
protected:
  void cycle_power() {
    dut.power_off();
    run_to(sched.now() + 10_ms);
    dut.power_on();
  }
  void save_configuration(const ConfigWords& c) {
    Words w = config_block(c);
    dut.write_outputs(w);
    w[1] = static_cast<std::uint16_t>(w[1] | cfgw::kSaveConfig);
    dut.write_outputs(w);
  }
  // Blend segments offset 1000 at 1100 then 2100 steps/s (L1118), saved to flash when LSW bit 5
  // is set as Move Program Mode falls (L2476).
  void program_blend(bool save) {
    command(msw::kProgramMove);
    for (std::int32_t vp : {1100, 2100}) {
      write(msw::kProgramMove | msw::kProgramSegment, kDrive, MoveWords{.value = 1000, .vp = vp});
      write(msw::kProgramMove, kDrive, MoveWords{.value = 1000, .vp = vp});
    }
    write(0, save ? static_cast<std::uint16_t>(kDrive | lsw::kSaveAssembled) : kDrive);
  }
};

// L2331: after Save Configuration the unit "stops responding to commands and you must cycle
// power"; Reset Errors does not bring it back. L2235: the saved configuration is used "on every
// power up"; L2243: it powers up in Command Mode, configured (Configuration Error 0, L2830).
TEST_F(Smd23ePowerCycle, AFlashSaveLocksTheUnitUntilPowerIsCycledAndIsLoadedAtPowerUp) {
  save_configuration(ConfigWords{.steps_per_turn = 400});
  ASSERT_EQ(dut.input_words()[9], 0xAAAA);
  command(msw::kResetErrors);
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(1_s);
  EXPECT_EQ(dut.step_position(sched.now()), 0); // still locked after Reset Errors
  EXPECT_EQ(dut.input_words()[9], 0xAAAA);

  cycle_power();
  EXPECT_FALSE(bit1(sw1::kConfigMode));
  EXPECT_FALSE(bit1(sw1::kConfigError));
  EXPECT_TRUE(bit1(sw1::kPositionInvalid)); // [MODEL] no absolute position
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(sched.now() + 1_s);
  EXPECT_EQ(position_word(), 100);
}

// L2235: "The new configuration is stored in RAM and is lost on power down unless you issue a
// command to store the new configuration in Flash"; L2284, L2372: then SW1 reads 0x6408.
TEST_F(Smd23ePowerCycle, AnUnsavedConfigurationIsLostAndTheUnitPowersUpUnconfigured) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(1_s);
  ASSERT_EQ(position_word(), 100);
  cycle_power();
  EXPECT_EQ(dut.input_words()[0], 0x6408);
  command(msw::kRelative, kDrive, MoveWords{.value = 100});
  run_to(sched.now() + 1_s);
  EXPECT_EQ(dut.step_position(sched.now()), 100); // refused: not configured (L2239)
}

// Errors are RAM: a Command Error does not survive a power cycle; nor does the position
// (Motor Position 0, Position Invalid) [MODEL: no absolute position]; the shaft stays put.
TEST_F(Smd23ePowerCycle, ErrorsAndThePositionAreLost) {
  save_configuration(ConfigWords{});
  cycle_power();
  command(msw::kRelative, kDrive, MoveWords{.value = 300});
  run_to(1_s);
  preset(5000);
  command(msw::kRelative, kDrive, MoveWords{.value = 9'000'000}); // beyond 8,388,607 (L875)
  ASSERT_TRUE(bit1(sw1::kCommandError));
  ASSERT_EQ(position_word(), 5000);
  cycle_power();
  EXPECT_FALSE(bit1(sw1::kCommandError));
  EXPECT_EQ(position_word(), 0);
  EXPECT_TRUE(bit1(sw1::kPositionInvalid));
  EXPECT_EQ(dut.step_position(sched.now()), 300);
}

// L1132, L1205: an assembled move saved to flash "is restored on power up and can be run as soon
// as you configure the SMD23E"; one not saved "stays in memory until power is removed".
TEST_F(Smd23ePowerCycle, OnlyAnAssembledMoveSavedToFlashSurvives) {
  save_configuration(ConfigWords{});
  cycle_power();
  program_blend(true); // the save locks the unit until power is cycled (L2476)
  command(msw::kRunAssembled);
  run_to(3_s);
  EXPECT_EQ(dut.step_position(sched.now()), 0);
  cycle_power();
  command(msw::kRunAssembled);
  run_to(sched.now() + 3_s);
  EXPECT_EQ(position_word(), 2000);
  EXPECT_FALSE(bit1(sw1::kCommandError));
}

TEST_F(Smd23ePowerCycle, AnUnsavedAssembledMoveIsLost) {
  save_configuration(ConfigWords{});
  cycle_power();
  program_blend(false);
  cycle_power();
  command(msw::kRunAssembled);
  run_to(sched.now() + 3_s);
  EXPECT_EQ(position_word(), 0);
  EXPECT_TRUE(bit1(sw1::kCommandError)); // nothing to run ([MODEL], as before any programming)
}

// While off the unit answers nothing and a running move stops where it is [MODEL].
TEST_F(Smd23ePowerCycle, WhileOffTheHostReadsZeroAndTheStepTrainStops) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 100'000});
  run_to(500_ms);
  const std::int64_t here = dut.step_position(sched.now());
  ASSERT_GT(here, 0);
  dut.power_off();
  EXPECT_EQ(dut.input_words(), Words{});
  run_to(2_s);
  EXPECT_EQ(dut.step_position(sched.now()), here);
}

} // namespace
} // namespace hilrig::models::smd23e::test
