// The ANS1's power cycle (power_off / power_on) through its host words: what flash keeps
// (stored programs, Save Global) and what RAM loses. Manual seeds/000_08a2edf5547d4d1e.txt.
#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::block;
using test::HostRig;

void cycle(HostRig& rig) {
  rig.device.power_off();
  rig.run_ms(5);
  rig.device.power_on();
  rig.step();
}

// CB3 for output 7: one pair ON `on` OFF `off` (w4, w5).
HostWords pair7(int on, int off) { return block(3, {10}, {{1, 7}, {4, on}, {5, off}}); }
int on7(HostRig& rig) { return rig.select(1, 7)[2]; } // DA1 w2: output 7's first ON setpoint

// L2224: a saved program lets "the ANS1 on power up" be programmed; L2236: "If power is cycled
// before these parameters are saved to a program, the ANS1 will power up with factory default
// settings". [MODEL] it powers up in the program last saved or loaded.
TEST(Ans1PowerCycle, TheSavedProgramSurvivesAndUnsavedChangesAreLost) {
  HostRig rig;
  ASSERT_EQ(rig.send(pair7(10, 20)), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 2}})), ErrorCode::None); // save program 2
  ASSERT_EQ(rig.send(pair7(30, 40)), ErrorCode::None);            // not saved
  ASSERT_EQ(on7(rig), 30);
  cycle(rig);
  EXPECT_EQ(on7(rig), 10);
  EXPECT_EQ(rig.select(0)[17], 2); // DA0 w17: the program loaded
  EXPECT_TRUE(rig.host.program_stored(2));
}

TEST(Ans1PowerCycle, WithNothingSavedItPowersUpWithFactoryDefaults) {
  HostRig rig;
  ASSERT_EQ(rig.send(pair7(10, 20)), ErrorCode::None);
  ASSERT_EQ(rig.send(block(2, {9}, {{3, 1000}})), ErrorCode::None); // FSC 1000 (CB2 w3)
  ASSERT_EQ(rig.select(0)[7], 1000);
  cycle(rig);
  EXPECT_EQ(on7(rig), 0);
  EXPECT_EQ(rig.select(0)[7], 360); // the factory Full Scale Count
}

// L2239: Save Global stores the CB2 and CB8 parameters to flash; a program does not hold them.
TEST(Ans1PowerCycle, SaveGlobalKeepsTheGlobalConfiguration) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(2, {9}, {{3, 1000}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {10})), ErrorCode::None);
  cycle(rig);
  EXPECT_EQ(rig.select(0)[7], 1000);
}

// L1816, L1820: Restore Factory Defaults (CB2 bit 5) restores "all parameters to their
// default settings and erase[s] all stored programming data ... Once erased, all programmed
// settings are lost and cannot be restored" - the Save Global flash copy (L2239) too. Saved:
// CPC 2000, FSC 1000 (CB2 w2, w3) and brake input 5 (CB8 w1); they survive one power cycle.
// After factory defaults and another power cycle: CPC 4,096 (L773), FSC 360 (L779) and no
// brake input (0 = disabled, L2106; it "has to be associated" before use, L1029).
TEST(Ans1PowerCycle, FactoryDefaultsEraseTheSavedGlobalParameters) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(2, {8, 9}, {{2, 2000}, {3, 1000}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(8, {8}, {{1, 5}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {10})), ErrorCode::None); // Save Global
  cycle(rig);
  ASSERT_EQ(rig.select(0)[6], 2000);
  ASSERT_EQ(rig.select(0)[7], 1000);
  ASSERT_EQ(rig.select(5)[1], 5);
  ASSERT_EQ(rig.send(block(2, {5})), ErrorCode::None); // Restore Factory Defaults
  EXPECT_EQ(rig.select(0)[6], 4096);
  EXPECT_EQ(rig.select(5)[1], 0);
  EXPECT_FALSE(rig.host.saved_global().has_value());
  cycle(rig);
  EXPECT_EQ(rig.select(0)[6], 4096);
  EXPECT_EQ(rig.select(0)[7], 360);
  EXPECT_EQ(rig.select(5)[1], 0);
  // Save Global works again afterwards: the next save is what flash holds.
  ASSERT_EQ(rig.send(block(2, {9}, {{3, 720}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {10})), ErrorCode::None);
  cycle(rig);
  EXPECT_EQ(rig.select(0)[6], 4096);
  EXPECT_EQ(rig.select(0)[7], 720);
}

// L2236: after Delete All Programs "Parameter values of the active program will remain in RAM.
// If power is cycled before these parameters are saved to a program, the ANS1 will power up
// with factory default settings". Until then DA0 w17 (L2338) names the program last read, which
// Save to slot 0 still writes (L2244); after the power cycle no program is active: w17 = 0, and
// Save to slot 0 has nowhere to go (1011, as on a fresh module).
TEST(Ans1PowerCycle, AfterDeleteAllProgramsAndAPowerCycleNoProgramIsActive) {
  HostRig rig;
  ASSERT_EQ(rig.send(pair7(10, 20)), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 5}})), ErrorCode::None); // save program 5
  ASSERT_EQ(rig.send(block(15, {5})), ErrorCode::None);           // delete all programs
  EXPECT_EQ(rig.select(0)[17], 5);
  EXPECT_EQ(on7(rig), 10); // still in RAM
  cycle(rig);
  EXPECT_EQ(rig.select(0)[17], 0);
  EXPECT_EQ(on7(rig), 0);
  EXPECT_EQ(rig.send(block(15, {9}, {{1, 0}})), ErrorCode::ParameterConflict);
}

// positions_fit.hpp [MODEL]: a stored program is never run with a position beyond the FSC in
// force (every position is 0..FSC-1, L1890-L1891). Program 4 holds the pair 10 -> 200; the
// saved global FSC is 200 (refused at power-up: factory defaults as after Load 40, no program
// active, 1011 shown until Clear Errors) or 201 (it runs).
TEST(Ans1PowerCycle, AStoredProgramBeyondTheSavedFullScaleCountDoesNotRun) {
  for (const int fsc : {200, 201}) {
    HostRig rig;
    ASSERT_EQ(rig.send(pair7(10, 200)), ErrorCode::None);
    ASSERT_EQ(rig.send(block(15, {9}, {{1, 4}})), ErrorCode::None); // save program 4
    ASSERT_EQ(rig.send(block(3, {6}, {{1, 7}})), ErrorCode::None);  // delete the pair in RAM
    ASSERT_EQ(rig.send(block(2, {9}, {{3, fsc}})), ErrorCode::None);
    ASSERT_EQ(rig.send(block(15, {10})), ErrorCode::None); // Save Global
    cycle(rig);
    const bool runs = fsc == 201;
    EXPECT_EQ(error_from_status(rig.host.read(0)), runs ? ErrorCode::None : ErrorCode::ParameterConflict)
        << fsc;
    EXPECT_EQ(rig.select(0)[7], fsc);
    EXPECT_EQ(rig.select(0)[17], runs ? 4 : 0) << fsc;
    EXPECT_EQ(rig.select(1, 7)[3], runs ? 200 : 0) << fsc;
    EXPECT_TRUE(rig.host.program_stored(4)) << fsc;
    EXPECT_EQ(rig.send(block(0, {4})), ErrorCode::None) << fsc;
  }
}

// L2306-L2309: a programming error stays through later valid blocks until Clear Errors; it is
// RAM, so a power cycle clears it too [MODEL]. Forced outputs (CB1 w4/w5) are RAM as well.
TEST(Ans1PowerCycle, ErrorsAndForcesDoNotSurvive) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(8, {9}, {{2, 256}})), ErrorCode::Parameter);
  ASSERT_EQ(rig.send(block(8, {9}, {{2, 10}})), ErrorCode::Parameter); // a valid block: still there
  rig.transact(block(1, {9}, {{4, 0x0001}, {5, 0x0001}}));             // force output 1 on
  ASSERT_TRUE(rig.device.outputs_forced());
  cycle(rig);
  EXPECT_EQ(error_from_status(rig.host.read(0)), ErrorCode::None);
  EXPECT_FALSE(rig.device.outputs_forced());
  EXPECT_EQ(rig.send(block(0, {})), ErrorCode::None);
}

// L1215: the Machine Revolutions counter "is stored in non-volatile memory"; the part counter
// is not [MODEL].
TEST(Ans1PowerCycle, TheMachineRevolutionsCountIsKept) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(11, {12}, {{1, 4}, {7, 0}, {8, 1234}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(11, {12}, {{1, 0}, {7, 0}, {8, 77}})), ErrorCode::None);
  ASSERT_EQ(rig.device.monitors().counters().value(CounterId::Revolutions), 1234U);
  cycle(rig);
  EXPECT_EQ(rig.device.monitors().counters().value(CounterId::Revolutions), 1234U);
  EXPECT_EQ(rig.device.monitors().counters().value(CounterId::PartCycle), 0U);
}

// [MODEL] while off the status words read 0 and a Transmit is not acted on; one already set at
// power-up is no edge: the host clears it and sets it again.
TEST(Ans1PowerCycle, WhileOffTheHostReadsZeroAndATransmitHeldAtPowerUpIsNoEdge) {
  HostRig rig;
  rig.device.power_off();
  rig.run_ms(1);
  EXPECT_EQ(rig.host.status(), HostWords{});
  HostWords w = pair7(10, 20);
  w[0] = static_cast<std::uint16_t>(w[0] | kTransmitBit);
  rig.host.write_block(w);
  rig.run_ms(1);
  rig.device.power_on();
  rig.run_ms(1);
  EXPECT_EQ(rig.host.read(0) & kAcknowledgeBit, 0);
  EXPECT_EQ(rig.device.output_setup(7).pairs[0].from, 0);
  EXPECT_EQ(rig.send(pair7(10, 20)), ErrorCode::None);
  EXPECT_EQ(on7(rig), 10);
}

} // namespace
} // namespace hilrig::models::ans1
