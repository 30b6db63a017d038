// Command blocks programmed through the 20 command words and read back through the data
// attribute blocks (spec §5.3, §5.5), with the manual's worked numbers where it gives them.
#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::block;
using test::HostRig;

std::int16_t as_int(std::uint16_t w) { return static_cast<std::int16_t>(w); }

TEST(HostGlobalBlock, CommandBlock2EchoesInDataAttribute0) {
  // W-04 scaling (CPC 3072, FSC 2700) with every other CB2 word applied.
  HostRig rig;
  ASSERT_EQ(
      rig.send(block(2, {7, 8, 9, 10, 11, 12, 13},
                     {{1, 0x13}, {2, 3072}, {3, 2700}, {4, -20}, {5, 100}, {6, 5}, {7, 0}, {8, 0x0F00}})),
      ErrorCode::None);
  const HostWords da0 = rig.select(0);
  EXPECT_EQ(da0[5], 0x13); // HoldOuts, XFltLatch, CntDir
  EXPECT_EQ(da0[6], 3072);
  EXPECT_EQ(da0[7], 2700);
  EXPECT_EQ(as_int(da0[8]), -20);
  EXPECT_EQ(da0[9], 100);
  EXPECT_EQ(da0[10], 5);
  EXPECT_EQ(da0[11], 0);
  EXPECT_EQ(da0[12], 0x0F00); // (inputs 9..12: input 5, the MPI, keeps its polarity)
  EXPECT_EQ(da0[13], 83);     // W-21: module ID 'S'
  EXPECT_EQ(da0[14], 39);     // product code (L2335)
  EXPECT_EQ(da0[17], 0);      // no program loaded
}

TEST(HostGlobalBlock, DefaultsAfterPowerUp) {
  // §6: CPC 4096, FSC 360, RPM filter 40960; no forces: DA0 w1 = 0x0000 and w2 = 0xFFFF.
  HostRig rig;
  const HostWords da0 = rig.select(0);
  EXPECT_EQ(da0[1], 0x0000);
  EXPECT_EQ(da0[2], 0xFFFF);
  EXPECT_EQ(da0[4], 0xFFFF);
  EXPECT_EQ(da0[6], 4096);
  EXPECT_EQ(da0[7], 360);
  EXPECT_EQ(da0[11], 40960);
}

TEST(HostGlobalBlock, W01AndW02PositionsReadInDataAttribute16) {
  HostRig rig;
  rig.use_slave_position();
  // W-02: raw 1024 of 4096 with FSC 360 -> GMP 90.
  rig.device.set_slave_position(1024);
  rig.run_ms(1);
  EXPECT_EQ(rig.select(16)[1], 90);
  // W-01: scaled position 10 (raw 114: floor(114 * 360 / 4096) = 10) with SMO -20 -> 350.
  ASSERT_EQ(rig.send(block(2, {10}, {{4, -20}})), ErrorCode::None);
  rig.device.set_slave_position(114);
  rig.run_ms(1);
  EXPECT_EQ(rig.select(16)[1], 350);
}

TEST(HostGlobalBlock, MachinePresetMakesGmpTheMachinePresetValue) {
  // CB2 bit 14 with bit 11: MPV from w5 (L1812). At GMP 90, MPV 10 -> SMO = 10 - 90 = -80.
  HostRig rig;
  rig.use_slave_position();
  rig.device.set_slave_position(1024);
  rig.run_ms(1);
  ASSERT_EQ(rig.send(block(2, {14, 11}, {{5, 10}, {6, 0}})), ErrorCode::None);
  rig.run_ms(1);
  EXPECT_EQ(rig.select(16)[1], 10);
  const HostWords da0 = rig.select(0);
  EXPECT_EQ(as_int(da0[8]), -80); // SMO in use, computed by the preset (L2329)
  EXPECT_EQ(da0[9], 10);
}

TEST(HostForces, CommandBlock1ForcesShowInDataAttribute0AndOnTheOutputs) {
  // Outputs 1 forced ON, 2 forced OFF; inputs 9 ON, 10 OFF (L1773-L1789, L2317-L2323).
  // Slave position: with an undecodable resolver every output would be off (§4.13).
  HostRig rig;
  rig.use_slave_position();
  rig.transact(block(1, {9, 10}, {{4, 0x0003}, {5, 0x0001}, {6, 0x0300}, {7, 0x0100}}));
  const HostWords da0 = rig.select(0);
  EXPECT_EQ(da0[1], 0x0001);
  EXPECT_EQ(da0[2], 0xFFFD); // inverted: output 2 forced off
  EXPECT_EQ(da0[3], 0x0100);
  EXPECT_EQ(da0[4], 0xFDFF); // inverted: input 10 forced off
  rig.run_ms(1);
  const HostWords da16 = rig.select(16);
  EXPECT_EQ(da16[9] & 0x0003, 0x0001);
  EXPECT_EQ(da16[5] & 0x0300, 0x0100);
}

TEST(HostForces, ForcesStayWhenTheirApplyBitIsZero) {
  HostRig rig;
  rig.transact(block(1, {9}, {{4, 0x0001}, {5, 0x0001}}));
  rig.transact(block(1, {8}, {{1, 0}, {4, 0}, {5, 0}}));
  EXPECT_EQ(rig.select(0)[1], 0x0001);
}

TEST(HostOutputBlocks, SetpointsEchoInDataAttribute1) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10, 13}, {{1, 7}, {4, 10}, {5, 20}, {16, 30}, {17, 100}, {18, 5}, {19, 3}})),
            ErrorCode::None);
  const HostWords da1 = rig.select(1, 7);
  EXPECT_EQ(da1[1], 7);
  EXPECT_EQ(da1[2], 10);
  EXPECT_EQ(da1[3], 20);
  EXPECT_EQ(da1[14], 30);
  EXPECT_EQ(da1[15], 100);
  EXPECT_EQ(da1[16], 5);
  EXPECT_EQ(da1[17], 3);
  // Delete the output's setpoint data (bit 6).
  ASSERT_EQ(rig.send(block(3, {6}, {{1, 7}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 7)[3], 0);
}

TEST(HostOutputBlocks, AdjustMovesSetpointsByOneAndWraps) {
  // CB4 (L1900-L1920): bit 14 = +1, 0 = -1 [A18]; From 0 - 1 wraps to FSC - 1 [MODEL].
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 2}, {4, 0}, {5, 50}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(4, {14, 7}, {{1, 2}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 2)[3], 51);
  ASSERT_EQ(rig.send(block(4, {6}, {{1, 2}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 2)[2], 359);
}

TEST(HostOutputBlocks, OffsetPresetAndLsPresetEchoInDataAttribute2) {
  HostRig rig;
  rig.use_slave_position();
  rig.device.set_slave_position(1024); // GMP 90
  rig.run_ms(1);
  ASSERT_EQ(rig.send(block(3, {8}, {{1, 5}, {2, -5}})), ErrorCode::None);
  EXPECT_EQ(as_int(rig.select(2, 5)[2]), -5);
  // Preset input 4, value 50, and apply the LS preset now: LSO = 50 - 90 = -40 (§4.3).
  ASSERT_EQ(rig.send(block(3, {14, 9}, {{1, 5}, {2, 4}, {3, 50}})), ErrorCode::None);
  const HostWords da2 = rig.select(2, 5);
  EXPECT_EQ(as_int(da2[2]), -40);
  EXPECT_EQ(da2[3], 4);
  EXPECT_EQ(da2[4], 50);
  rig.run_ms(1);
  const HostWords da16 = rig.select(16, 5);
  EXPECT_EQ(da16[18], 5);
  EXPECT_EQ(da16[19], 50); // LS position = (90 - 40) mod 360
}

TEST(HostOutputBlocks, TimingEchoesInDataAttribute2) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(5, {8, 11}, {{1, 3}, {2, 10}, {3, 20}, {4, 500}})), ErrorCode::None);
  HostWords da2 = rig.select(2, 3);
  EXPECT_EQ(da2[5], 10); // lead
  EXPECT_EQ(da2[6], 0);
  EXPECT_EQ(da2[7], 20); // trail
  EXPECT_EQ(da2[8], 500);
  EXPECT_NE(da2[9], 0); // Time-Only
  ASSERT_EQ(rig.send(block(5, {9, 10}, {{1, 3}, {2, 5}, {3, 9999}, {4, 250}})), ErrorCode::None);
  da2 = rig.select(2, 3);
  EXPECT_EQ(da2[5], 5);    // fixed advance
  EXPECT_EQ(da2[6], 9999); // VAT
  EXPECT_EQ(da2[8], 250);
  EXPECT_EQ(da2[9], 0); // Time-or-Position
  ASSERT_EQ(rig.send(block(5, {6}, {{1, 3}})), ErrorCode::None);
  da2 = rig.select(2, 3);
  EXPECT_EQ(da2[5], 0);
  EXPECT_EQ(da2[6], 0);
  EXPECT_EQ(da2[8], 0);
}

TEST(HostOutputBlocks, EnablingEchoesInDataAttributes3And2) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(6, {8}, {{1, 9}, {2, 1}, {3, 2}, {4, 3}, {18, 10}, {19, 20}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(6, {9, 10}, {{1, 9}, {2, -100}, {3, 100}, {4, 256}})), ErrorCode::None);
  const HostWords da3 = rig.select(3, 9);
  EXPECT_EQ(da3[2], 1);
  EXPECT_EQ(da3[3], 2);
  EXPECT_EQ(da3[4], 3);
  EXPECT_EQ(da3[5], 0);
  EXPECT_EQ(da3[18], 10);
  EXPECT_EQ(da3[19], 20);
  const HostWords da2 = rig.select(2, 9);
  EXPECT_EQ(as_int(da2[10]), -100);
  EXPECT_EQ(da2[11], 100);
  EXPECT_EQ(da2[12], 256);
}

TEST(HostMonitorBlocks, DieProtectionBrakeShiftRegisterAndCycleEcho) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(7, {8, 9, 10}, {{1, 12}, {2, 5}, {3, 3}, {4, 100}, {5, 200}, {12, 1}})),
            ErrorCode::None);
  ASSERT_EQ(
      rig.send(block(8, {8, 9, 10, 11, 12, 13}, {{1, 3}, {2, 20}, {3, 100}, {4, 9}, {5, 200}, {6, 10}})),
      ErrorCode::None);
  ASSERT_EQ(rig.send(block(9, {8}, {{1, 2}, {2, 10}, {3, 20}, {4, 30}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(10, {8, 9}, {{1, 45}, {2, 3}, {3, 2}})), ErrorCode::None);
  const HostWords da4 = rig.select(4, 1, 5);
  EXPECT_EQ(da4[1], 12);
  EXPECT_EQ(da4[2], 5);
  EXPECT_EQ(da4[3], 3);
  EXPECT_EQ(da4[4], 100);
  EXPECT_EQ(da4[5], 200);
  EXPECT_EQ(da4[12], 1);
  const HostWords da5 = rig.select(5);
  EXPECT_EQ((HostWords{da5[0], 3, 20, 100, 9, 200, 10}), da5);
  const HostWords da6 = rig.select(6);
  EXPECT_EQ(da6[1], 2);
  EXPECT_EQ(da6[2], 10);
  EXPECT_EQ(da6[3], 20);
  EXPECT_EQ(da6[4], 30);
  const HostWords da7 = rig.select(7);
  EXPECT_EQ(da7[1], 45);
  EXPECT_EQ(da7[2], 3);
  EXPECT_EQ(da7[3], 2);
  // Delete: the brake monitor (CB8 bit 5) and the DP data of input 5 (CB7 bit 6).
  ASSERT_EQ(rig.send(block(8, {5})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(7, {6}, {{2, 5}})), ErrorCode::None);
  EXPECT_EQ(rig.select(5)[1], 0);
  EXPECT_EQ(rig.select(4, 1, 5)[3], 0);
}

TEST(HostCounterBlocks, W14AndW15LimitsSplitHighWordFirst) {
  // W-14: limit 40,000 = 0x0000 9C40 -> high 0, low 0x9C40 (-25,536 on a signed host).
  // W-15: limit 999,999,999 = 0x3B9A C9FF -> 15258 and 51711 (-13,825 signed).
  HostRig rig;
  ASSERT_EQ(rig.send(block(11, {8, 9, 11}, {{1, 1}, {2, 14}, {3, 1}, {5, 0}, {6, 0x9C40}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(11, {11}, {{1, 0}, {5, 0x3B9A}, {6, 0xC9FF}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(11, {10}, {{1, 3}, {4, 1}})), ErrorCode::None);
  const HostWords da8 = rig.select(8);
  EXPECT_EQ(da8[2], 15258);
  EXPECT_EQ(da8[3], 51711);
  EXPECT_EQ(as_int(da8[3]), -13825);
  EXPECT_EQ(da8[4], 14); // batch 1 output
  EXPECT_EQ(da8[5], 1);  // batch 1 output mode
  EXPECT_EQ(da8[7], 0);
  EXPECT_EQ(da8[8], 0x9C40);
  EXPECT_EQ(as_int(da8[8]), -25536);
  EXPECT_EQ(da8[16], 1); // batch 3 increment mode
}

TEST(HostCounterBlocks, PresetShowsInDataAttribute17) {
  // 123,456,789 = 0x075B CD15.
  HostRig rig;
  ASSERT_EQ(rig.send(block(11, {12}, {{1, 2}, {7, 0x075B}, {8, 0xCD15}})), ErrorCode::None);
  const HostWords da17 = rig.select(17);
  EXPECT_EQ(da17[6], 0x075B);
  EXPECT_EQ(da17[7], 0xCD15);
}

TEST(HostPrograms, SaveLoadFactoryAndDelete) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 7}, {4, 10}, {5, 20}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9, 10}, {{1, 2}})), ErrorCode::None); // save program 2 and global
  EXPECT_EQ(rig.select(0)[17], 2);
  EXPECT_TRUE(rig.host.saved_global().has_value());
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 7}, {4, 30}, {5, 40}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {8}, {{1, 2}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 7)[2], 10);
  // Slot 40: factory defaults into RAM (L2229); the stored program survives.
  ASSERT_EQ(rig.send(block(15, {8}, {{1, 40}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 7)[2], 0);
  EXPECT_TRUE(rig.host.program_stored(2));
  // Save to "the active program" (slot 0) after loading 2, then delete every stored program.
  ASSERT_EQ(rig.send(block(15, {8}, {{1, 2}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 0}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {5})), ErrorCode::None);
  EXPECT_FALSE(rig.host.program_stored(2));
  EXPECT_EQ(rig.send(block(15, {8}, {{1, 2}})), ErrorCode::Parameter);
}

TEST(HostPrograms, RestoreFactoryDefaultsErasesStoredProgramsToo) {
  // CB2 bit 5 (§5.3): defaults in RAM and all stored programs erased.
  HostRig rig;
  ASSERT_EQ(rig.send(block(2, {9}, {{3, 1000}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 1}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(2, {5})), ErrorCode::None);
  EXPECT_EQ(rig.select(0)[7], 360);
  EXPECT_FALSE(rig.host.program_stored(1));
}

// Moves the slave position: at each whole ms t up to `to` the position becomes pos(t), exactly
// at t (scheduled, so it does not depend on the phase of the device's scan grid).
template <class Pos> void run_positions(HostRig& rig, std::int64_t to, Pos pos) {
  const std::int64_t now_ms = rig.scheduler.now() / milliseconds(1);
  rig.device.set_slave_position(pos(now_ms));
  for (std::int64_t t = now_ms + 1; t <= to; ++t) {
    rig.scheduler.at(milliseconds(t), [&rig, pos, t] { rig.device.set_slave_position(pos(t)); });
  }
  rig.scheduler.run_until(milliseconds(to));
}

TEST(HostLiveData, BrakeStopTimeAndOverrunThroughTheHost) {
  // Brake input 3 driven by input forces; the press runs at 41 counts/ms. By hand (1 ms
  // monitor ticks): the force written at ~100 ms is first seen at tick 101 (application); the
  // position stops changing at 251 ms, 150 ms later; the 125 ms window is first still at tick
  // 376 -> stop timer 275 ms -> 150 ms reported (W-17), over the 100 ms limit.
  for (Variant v : {Variant::Correct, Variant::BrakeNeverFaults}) {
    HostRig rig(v);
    rig.use_slave_position();
    ASSERT_EQ(rig.send(block(8, {8, 9, 12, 13}, {{1, 3}, {2, 10}, {5, 100}, {6, 10}})), ErrorCode::None);
    rig.transact(block(1, {10}, {{6, 0x0004}, {7, 0x0004}})); // released
    const auto pos = [](std::int64_t t) { return 41 * std::min<std::int64_t>(t, 251); };
    run_positions(rig, 100, pos);
    EXPECT_NE(rig.select(16)[9] & (1U << 9), 0U) << "stop overrun output 10 on while healthy";
    EXPECT_NE(rig.select(19)[2], 0) << "DA19 w2: brake input active (released)";
    rig.transact(block(1, {10}, {{6, 0x0004}, {7, 0x0000}})); // applied at t = 100
    run_positions(rig, 500, pos);
    const HostWords da19 = rig.select(19);
    EXPECT_EQ(da19[2], 0);
    EXPECT_EQ(da19[6], 150);
    const bool output_on = (rig.select(16)[9] & (1U << 9)) != 0;
    if (v == Variant::Correct) {
      EXPECT_FALSE(output_on) << "stop overrun: output 10 off [MODEL A5]";
      EXPECT_EQ(rig.select(16)[17] & (1U << 9), 0U) << "DA16 w17: user output in its disabled state";
    } else {
      EXPECT_TRUE(output_on) << "the never-faults variant keeps output 10 on";
    }
  }
}

TEST(HostLiveData, DieProtectionFaultThroughTheHost) {
  // Input 5 Normally False with fault output 12 (action 0); forcing input 5 active is a fault.
  for (Variant v : {Variant::Correct, Variant::DieProtectionNeverCounts}) {
    HostRig rig(v);
    rig.use_slave_position(); // a valid position: no transducer fault holding outputs off
    ASSERT_EQ(rig.send(block(7, {8, 9, 10}, {{1, 12}, {2, 5}, {3, 2}, {12, 0}})), ErrorCode::None);
    rig.run_ms(1);
    HostWords da18 = rig.select(18, 1, 5);
    EXPECT_EQ(da18[2], 1U << 11) << "DP output 12, no fault";
    EXPECT_EQ(da18[7], 0);
    rig.transact(block(1, {10}, {{6, 0x0010}, {7, 0x0010}}));
    rig.run_ms(1);
    da18 = rig.select(18, 1, 5);
    EXPECT_EQ(da18[3], 0x0010); // the DP input's state
    EXPECT_EQ(da18[4], 0x0010); // first to fault
    EXPECT_EQ(da18[5], 0x0010); // faulted this cycle
    if (v == Variant::Correct) {
      EXPECT_EQ(da18[7], 1);
      EXPECT_EQ(da18[2], 0);
      EXPECT_EQ(rig.select(16)[9] & (1U << 11), 0U);
    } else {
      EXPECT_EQ(da18[7], 0);
      EXPECT_NE(rig.select(16)[9] & (1U << 11), 0U);
    }
  }
}

TEST(HostLiveData, CountersAndOverflowOutputThroughTheHost) {
  // 41 counts/ms of 4096: GMP passes 0 at ~100, 200 and 300 ms. Part Cycle limit 2 with
  // output 13 in mode 1: on from the 2nd pass until the 3rd (L1224).
  HostRig rig;
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(11, {8, 9, 11}, {{1, 0}, {2, 13}, {3, 1}, {6, 2}})), ErrorCode::None);
  const auto pos = [](std::int64_t t) { return 41 * t; };
  run_positions(rig, 250, pos);
  HostWords da17 = rig.select(17);
  EXPECT_EQ(da17[3], 2);  // part cycles
  EXPECT_EQ(da17[11], 2); // revolutions
  EXPECT_EQ(da17[14], 1U << 12);
  EXPECT_EQ(da17[15], 1U << 12);
  EXPECT_NE(rig.select(16)[9] & (1U << 12), 0U);
  run_positions(rig, 350, pos);
  da17 = rig.select(17);
  EXPECT_EQ(da17[3], 3);
  EXPECT_EQ(da17[13], 3); // good parts
  EXPECT_EQ(da17[15], 0);
  EXPECT_EQ(rig.select(16)[9] & (1U << 12), 0U);
}

TEST(HostLiveData, RpmClampedWhenAnAdvanceIsLongerThanACycle) {
  // L2313: a 32,767 ms lead at ~600 RPM is far more than one cycle (100 ms).
  HostRig rig;
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 1}, {4, 10}, {5, 20}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(5, {8}, {{1, 1}, {2, 32767}, {3, 0}})), ErrorCode::None);
  EXPECT_EQ(rig.host.read(0) & 0x0080, 0);
  run_positions(rig, 100, [](std::int64_t t) { return 41 * t; });
  EXPECT_NE(rig.host.read(0) & 0x0080, 0);
}

} // namespace
} // namespace hilrig::models::ans1
