// The Transmit/Acknowledge handshake and status word 0 (spec §5.1, §5.4; L1705, L2284-L2315).
#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::block;
using test::HostRig;
using namespace hilrig::literals;

// CB4 "+1 on From-1 of output 2": each execution moves From by one, so it counts executions.
HostWords adjust_from_plus_one() { return block(4, {14, 6}, {{1, 2}}); }

int from_of_output_2(HostRig& rig) { return rig.select(1, 2)[2]; }

TEST(HostHandshake, BlockActsOnlyOnTheTransmitRisingEdge) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 2}, {4, 10}, {5, 20}})), ErrorCode::None);
  // Words written with Transmit = 0 are ignored (L1705).
  rig.host.write_block(adjust_from_plus_one());
  rig.step();
  rig.step();
  EXPECT_EQ(from_of_output_2(rig), 10);
  // The 0->1 edge executes once; holding Transmit = 1 does not execute again.
  HostWords w = adjust_from_plus_one();
  w[0] = static_cast<std::uint16_t>(w[0] | kTransmitBit);
  rig.host.write_block(w);
  for (int i = 0; i < 5; ++i) rig.step();
  EXPECT_NE(rig.host.read(0) & kAcknowledgeBit, 0);
  w[0] = static_cast<std::uint16_t>(w[0] & ~kTransmitBit);
  rig.host.write_block(w);
  rig.step();
  EXPECT_EQ(from_of_output_2(rig), 11);
}

TEST(HostHandshake, WordsChangedWhileTransmitIsHighAreIgnoredUntilTheNextEdge) {
  HostRig rig;
  HostWords w = block(3, {10}, {{1, 2}, {4, 10}, {5, 20}});
  w[0] = static_cast<std::uint16_t>(w[0] | kTransmitBit);
  rig.host.write_block(w);
  rig.step();
  rig.host.write(4, 30); // too late: the block was taken at the edge
  rig.host.write(5, 40);
  rig.step();
  rig.host.write(0, static_cast<std::uint16_t>(w[0] & ~kTransmitBit));
  rig.step();
  const HostWords da1 = rig.select(1, 2);
  EXPECT_EQ(da1[2], 10);
  EXPECT_EQ(da1[3], 20);
}

TEST(HostHandshake, AcknowledgeFollowsTransmitStepByStep) {
  HostRig rig;
  rig.host.write_block(block(0, {}));
  rig.step();
  EXPECT_FALSE(rig.host.acknowledge());
  rig.host.write(0, kTransmitBit);
  EXPECT_FALSE(rig.host.acknowledge()); // nothing happens until the device scans
  rig.step();
  EXPECT_FALSE(rig.host.acknowledge()); // this scan executed the block
  rig.step();
  EXPECT_TRUE(rig.host.acknowledge()); // the next one wrote the response (L1705)
  rig.host.write(0, 0);
  EXPECT_TRUE(rig.host.acknowledge());
  rig.step();
  EXPECT_FALSE(rig.host.acknowledge());
}

TEST(HostHandshake, WordsReadWithAcknowledgeShowTheBlockInForce) {
  // L1705: on the Transmit edge the ANS1 acts upon the block, writes the response to the input
  // data, then sets Acknowledge: what a host reads with Acknowledge is the block in force.
  // A still shaft at count 0 (slave mode) with SMO g: GMP = g mod 360 (L780); output 1 with
  // LS offset 10 reads LS position (GMP + 10) mod 360 (DA16 w19, L1867, L2559), and its pair
  // [100, 101) (L1890) turns it on at LS position 100 only, i.e. at GMP 90 (DA16 w9, L2542).
  HostRig rig;
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(3, {8, 10}, {{1, 1}, {2, 10}, {4, 100}, {5, 101}})), ErrorCode::None);
  rig.select(16, 1);
  for (int smo = -359; smo <= 359; ++smo) {
    const HostWords status = rig.transact(block(2, {10}, {{4, smo}}));
    const int gmp = (smo + 360) % 360;
    ASSERT_EQ(status[1], gmp) << "SMO " << smo;
    ASSERT_EQ(status[19], (gmp + 10) % 360) << "SMO " << smo;
    ASSERT_EQ(status[9] & 1U, gmp == 90 ? 1U : 0U) << "SMO " << smo;
  }
  // An output force (CB1 w4/w5, L1773) shows in the output states read with Acknowledge.
  for (int n = 2; n <= kOutputCount; ++n) {
    const int mask = 1 << (n - 1);
    const HostWords status = rig.transact(block(1, {9}, {{4, mask}, {5, mask}}));
    ASSERT_EQ(status[9], mask) << "output " << n; // output 1 is off at GMP 359
  }
}

TEST(HostHandshake, RejectedBlockIsStillAcknowledged) {
  // [MODEL A43]: the host needs Ack to read the error code.
  HostRig rig;
  const HostWords status = rig.transact(block(13, {}));
  EXPECT_NE(status[0] & kAcknowledgeBit, 0);
  EXPECT_EQ(error_from_status(status[0]), ErrorCode::CommandWord);
}

TEST(HostStatusWord, CarriesTheNumberOfTheReturnedBlock) {
  // L2284: bits 4..0 = the data attribute block; 16..20 need all five bits.
  HostRig rig;
  EXPECT_EQ(rig.host.read(0) & 0x1F, 0); // DA0 after power-up [MODEL]
  for (int da : {0, 1, 2, 3, 4, 5, 6, 7, 8, 16, 17, 18, 19, 20}) {
    EXPECT_EQ(rig.select(da)[0] & 0x1F, da) << "DA" << da;
  }
  EXPECT_EQ(rig.host.read(0) & 0x0020, 0); // bit 5 is always 0
}

TEST(HostStatusWord, W18HeartbeatTogglesEvery500ms) {
  // W-18 (L2297): status bit 14 flips every 500 ms.
  HostRig rig;
  rig.scheduler.run_until(499_ms);
  EXPECT_EQ(rig.host.read(0) & 0x4000, 0);
  rig.scheduler.run_until(500_ms);
  EXPECT_NE(rig.host.read(0) & 0x4000, 0);
  rig.scheduler.run_until(999_ms);
  EXPECT_NE(rig.host.read(0) & 0x4000, 0);
  rig.scheduler.run_until(1000_ms);
  EXPECT_EQ(rig.host.read(0) & 0x4000, 0);
}

TEST(HostStatusWord, OutputForcedBitFollowsTheOutputForces) {
  // L2314: bit 6 while any output is forced; forces come from CB1 bit 9 (w4 enable, w5 state).
  HostRig rig;
  EXPECT_EQ(rig.host.read(0) & 0x0040, 0);
  rig.transact(block(1, {9}, {{4, 0x0001}, {5, 0x0001}}));
  EXPECT_NE(rig.host.read(0) & 0x0040, 0);
  rig.transact(block(1, {9}, {{4, 0}, {5, 0}}));
  EXPECT_EQ(rig.host.read(0) & 0x0040, 0);
}

TEST(HostStatusWord, ResolverFaultBitShowsAnUndecodableResolver) {
  // L2299: with the resolver selected and no stator signals the position cannot be decoded.
  HostRig rig;
  rig.run_ms(5);
  EXPECT_NE(rig.host.read(0) & 0x1000, 0);
  rig.use_slave_position(); // no resolver in use
  rig.run_ms(1);
  EXPECT_NE(rig.host.read(0) & 0x1000, 0); // latched (XFltLatch = 0) until Clear Errors
  rig.transact(block(0, {4}));             // Clear Errors drops the latched fault (L1839)
  rig.run_ms(5);
  EXPECT_EQ(rig.host.read(0) & 0x1000, 0);
}

TEST(HostStatusWord, HardwareFaultBitOnAChecksumErrorUntilClearErrors) {
  // L2298: a checksum error in the last program read from memory. Programs are stored with
  // CB15 bit 9 and loaded with bit 8.
  HostRig rig;
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 3}})), ErrorCode::None);
  rig.host.corrupt_program(3);
  rig.transact(block(15, {8}, {{1, 3}}));
  EXPECT_NE(rig.host.read(0) & 0x2000, 0);
  rig.transact(block(0, {4}));
  EXPECT_EQ(rig.host.read(0) & 0x2000, 0);
}

} // namespace
} // namespace hilrig::models::ans1
