// SSI signal faults: each is either detected by the master's handshake checks and parity,
// or changes the decoded value in the hand-computed way.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "signals/ssi_master.hpp"
#include "signals/ssi_slave.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

// One 125 kHz frame (T = 8 us) of `f` carrying `value`, with `faults` applied before it.
SsiReading one_frame(const SsiFrameFormat& f, std::uint32_t value, const SsiSlaveFaults& faults) {
  SsiMasterParams mp;
  mp.frame_bits = f.frame_bits;
  mp.frame_period = 500_us;
  const SsiMaster master(mp);
  SsiSlaveParams sp;
  sp.format = f;
  SsiSlave slave(sp, [value](Nanos) { return value; });
  std::vector<Edge> data;
  if (auto e = slave.set_faults(faults, 0_ns)) data.push_back(*e);
  const Nanos start = 100_us;
  for (const Edge& e : respond(slave, master.clock_schedule(start, 1), start + 500_us)) data.push_back(e);
  return master.read_frame(LineHistory(Level::High, data), start);
}

SsiFrameFormat twelve_bits(SsiCode code = SsiCode::Binary) {
  SsiFrameFormat f;
  f.frame_bits = 12;
  f.data_bits = 12;
  f.code = code;
  return f;
}

TEST(SsiFaults, NoFaultReadsTheValue) {
  const SsiReading r = one_frame(twelve_bits(), 1000, {});
  EXPECT_EQ(r.word, 1000u);
  EXPECT_TRUE(r.ready);
  EXPECT_TRUE(r.released);
}

TEST(SsiFaults, StuckHighGivesTheAllOnesNoTransducerWord) {
  // ssi7361.md §4 / M-03: a line stuck high reads as all ones (0x1FFFFFF for 25 bits).
  SsiSlaveFaults f;
  f.stuck = SsiStuck::High;
  const SsiReading r = one_frame(ssi7361_frame(), 12345, f);
  EXPECT_EQ(r.word, 0x01FF'FFFFu);
  EXPECT_EQ(r.word, 33'554'431u);
}

TEST(SsiFaults, StuckLowFailsTheReadyCheck) {
  SsiSlaveFaults f;
  f.stuck = SsiStuck::Low;
  const SsiReading r = one_frame(ssi7361_frame(), 12345, f);
  EXPECT_EQ(r.word, 0u);
  EXPECT_FALSE(r.ready);    // DATA must idle high before F1
  EXPECT_FALSE(r.released); // and return high after the monoflop
}

TEST(SsiFaults, BitFlipAtStreamBitK) {
  // Stream bit k of a 12-bit frame has weight 2^(12-k): flipping bit 3 of 1000 (0x3E8)
  // toggles 0x200 -> 0x1E8 = 488.
  SsiSlaveFaults f;
  f.flip_stream_bit = 3;
  EXPECT_EQ(one_frame(twelve_bits(), 1000, f).word, 488u);
  f.flip_stream_bit = 12; // the LSB: 1000 -> 1001
  EXPECT_EQ(one_frame(twelve_bits(), 1000, f).word, 1001u);
}

TEST(SsiFaults, BitFlipIsCaughtByParity) {
  SsiFrameFormat fmt = twelve_bits();
  fmt.frame_bits = 13;
  fmt.parity = SsiParity::Even;
  SsiSlaveFaults f;
  f.flip_stream_bit = 5;
  const SsiReading bad = one_frame(fmt, 1000, f);
  EXPECT_FALSE(decompose_frame(fmt, bad.word).parity_ok);
  const SsiReading good = one_frame(fmt, 1000, {});
  EXPECT_TRUE(decompose_frame(fmt, good.word).parity_ok);
  EXPECT_EQ(decompose_frame(fmt, good.word).value, 1000u);
}

TEST(SsiFaults, LateResponseWithinHalfAPeriodIsHarmless) {
  // The master samples half a period (4 us) after R_k; data 3 us late is still read right.
  SsiSlaveFaults f;
  f.late_response = 3_us;
  EXPECT_EQ(one_frame(twelve_bits(), 1000, f).word, 1000u);
}

TEST(SsiFaults, LateResponseBeyondHalfAPeriodShiftsTheWord) {
  // 5 us late: at sample k*T the line still shows bit k-1, and before bit 1 the latch-low
  // level (0). So the word reads shifted right by one: 1000 >> 1 = 500.
  SsiSlaveFaults f;
  f.late_response = 5_us;
  EXPECT_EQ(one_frame(twelve_bits(), 1000, f).word, 500u);
}

TEST(SsiFaults, GrayGlitchOnTheMsbTrackReflectsTheValue) {
  // Reflected Gray code: g(v) ^ 2^(n-1) = g(2^n - 1 - v). A glitch on the MSB track turns
  // 1000 into 4095 - 1000 = 3095 after decoding, where binary would give 1000 + 2048 = 3048.
  SsiSlaveFaults f;
  f.gray_glitch_mask = 0x800;
  const SsiReading gray = one_frame(twelve_bits(SsiCode::Gray), 1000, f);
  EXPECT_EQ(decompose_frame(twelve_bits(SsiCode::Gray), gray.word).value, 3095u);
  const SsiReading bin = one_frame(twelve_bits(), 1000, f);
  EXPECT_EQ(bin.word, 3048u);
}

TEST(SsiFaults, GrayGlitchOnBitOneFlipsTheLowBits) {
  // Gray bit 1 flipped: decoding carries it into bits 1 and 0. By hand: g(1000) = 1000 ^ 500
  // = 540 = 0x21C; 0x21C ^ 0x2 = 0x21E; prefix XOR from the MSB of 0x21E = 0x3EB = 1003.
  SsiSlaveFaults f;
  f.gray_glitch_mask = 0x2;
  const SsiReading r = one_frame(twelve_bits(SsiCode::Gray), 1000, f);
  EXPECT_EQ(decompose_frame(twelve_bits(SsiCode::Gray), r.word).value, 1003u);
}

TEST(SsiFaults, FaultsCanBeClearedBetweenFrames) {
  SsiMasterParams mp;
  mp.frame_bits = 12;
  const SsiMaster master(mp);
  SsiSlaveParams sp;
  sp.format = twelve_bits();
  SsiSlave slave(sp, [](Nanos) { return 1000u; });
  std::vector<Edge> data;
  SsiSlaveFaults flip;
  flip.flip_stream_bit = 1;
  (void)slave.set_faults(flip, 0_ns);
  for (const Edge& e : respond(slave, master.clock_schedule(0_ns, 1), 400_us)) data.push_back(e);
  (void)slave.set_faults({}, 400_us);
  for (const Edge& e : respond(slave, master.clock_schedule(500_us, 1), 900_us)) data.push_back(e);
  const auto r = master.read_frames(LineHistory(Level::High, data), 0_ns, 2);
  EXPECT_EQ(r[0].word, 1000u + 2048u);
  EXPECT_EQ(r[1].word, 1000u);
}

} // namespace
} // namespace hilrig::signals
