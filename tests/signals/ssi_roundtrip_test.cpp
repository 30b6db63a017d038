// SSI slave + master on one data line: clock timing of the 7361 (hand-computed from
// ssi7361.md §2.1) and value round trips for every width 2..32, binary and Gray.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "signals/gray_code.hpp"
#include "signals/ssi_master.hpp"
#include "signals/ssi_slave.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

std::size_t count_level(const std::vector<Edge>& edges, Level l) {
  std::size_t n = 0;
  for (const Edge& e : edges) n += e.level == l ? 1u : 0u;
  return n;
}

TEST(SsiMasterClock, SevenThreeSixOneFrameAt125kHzLasts192us) {
  // T = 8 us; F_j = (j-1)T, so F1 -> F25 = 24 * 8 us = 192 us; R25 = 24.5 T = 196 us.
  const SsiMaster m(ssi7361_master(false));
  EXPECT_EQ(m.clock_period(), 8_us);
  const std::vector<Edge> clk = m.clock_schedule(0_ns, 1);
  ASSERT_EQ(clk.size(), 50u);
  EXPECT_EQ(count_level(clk, Level::Low), 25u);
  EXPECT_EQ(count_level(clk, Level::High), 25u);
  EXPECT_EQ(clk.front(), (Edge{0_ns, Level::Low}));
  EXPECT_EQ(clk[48], (Edge{192_us, Level::Low}));  // F25
  EXPECT_EQ(clk[49], (Edge{196_us, Level::High})); // R25, clock left high
  // TINT 500 us: TINT - TIDL = 500 - 308 = 192 us = F1 -> F25 (digest §2.1).
  EXPECT_EQ(m.frame_period() - 308_us, clk[48].time - clk[0].time);
}

TEST(SsiMasterClock, SevenThreeSixOneAt500kHz) {
  // T = 2 us: F25 at 48 us; TINT 250 us and TINT - TIDL = 250 - 202 = 48 us.
  const SsiMaster m(ssi7361_master(true));
  const std::vector<Edge> clk = m.clock_schedule(10_us, 2);
  ASSERT_EQ(clk.size(), 100u);
  EXPECT_EQ(clk[48].time - clk[0].time, 48_us);
  EXPECT_EQ(clk[48].time - clk[0].time, m.frame_period() - 202_us);
  EXPECT_EQ(clk[50].time, 260_us); // second frame's F1, one TINT later
}

TEST(SsiMasterClock, RejectsABurstLongerThanTheFramePeriod) {
  SsiMasterParams p = ssi7361_master(false);
  p.frame_period = 196_us; // R25 is at 196 us
  EXPECT_THROW(SsiMaster{p}, std::invalid_argument);
}

// Plays `values` through a slave and a master at 500 kHz and returns what the master decoded.
struct RoundTrip {
  std::vector<SsiReading> readings;
  std::vector<SsiFrameFields> fields;
};

RoundTrip round_trip(const SsiFrameFormat& f, const std::vector<std::uint32_t>& values) {
  SsiMasterParams mp;
  mp.clock_hz = 500'000.0;
  mp.frame_bits = f.frame_bits;
  mp.frame_period = 120_us; // 32 bits take 64 us; leaves > TM of quiet time
  const SsiMaster master(mp);
  const Nanos first = 20_us;
  SsiSlaveParams sp;
  sp.format = f;
  SsiSlave slave(sp,
                 [&](Nanos t) { return values.at(static_cast<std::size_t>((t - first) / mp.frame_period)); });
  const std::vector<Edge> clock = master.clock_schedule(first, values.size());
  const std::vector<Edge> data =
      respond(slave, clock, first + mp.frame_period * static_cast<std::int64_t>(values.size()));
  RoundTrip out;
  out.readings = master.read_frames(LineHistory(Level::High, data), first, values.size());
  for (const SsiReading& r : out.readings) out.fields.push_back(decompose_frame(f, r.word));
  return out;
}

class SsiRoundTrip : public ::testing::TestWithParam<SsiCode> {};

TEST_P(SsiRoundTrip, EveryWidthTwoToThirtyTwoSeededAndPatterns) {
  std::mt19937 rng(7361);
  for (unsigned n = 2; n <= 32; ++n) {
    SsiFrameFormat f;
    f.frame_bits = n;
    f.data_bits = n;
    f.code = GetParam();
    const std::uint32_t all = low_mask(n);
    std::vector<std::uint32_t> values = {0u, all, 0x5555'5555u & all, 0xAAAA'AAAAu & all, 1u, 1u << (n - 1)};
    for (int i = 0; i < 40; ++i) values.push_back(static_cast<std::uint32_t>(rng()) & all);
    const RoundTrip rt = round_trip(f, values);
    ASSERT_EQ(rt.fields.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_EQ(rt.fields[i].value, values[i]) << "n=" << n << " frame " << i;
      EXPECT_TRUE(rt.readings[i].ready) << "n=" << n << " frame " << i;
      EXPECT_TRUE(rt.readings[i].released) << "n=" << n << " frame " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Codes, SsiRoundTrip, ::testing::Values(SsiCode::Binary, SsiCode::Gray));

TEST(SsiRoundTrip, StatusAndParityTravelWithTheData) {
  SsiFrameFormat f = ssi7361_frame(1, 20, SsiCode::Gray);
  f.status_bits = 2;
  f.parity = SsiParity::Even;
  SsiMasterParams mp = ssi7361_master(false);
  const SsiMaster master(mp);
  SsiSlaveParams sp;
  sp.format = f;
  SsiSlave slave(sp, [](Nanos) { return 0xABCDEu; });
  slave.set_status(0b10);
  const std::vector<Edge> clock = master.clock_schedule(0_ns, 1);
  const std::vector<Edge> data = respond(slave, clock, 500_us);
  const SsiReading r = master.read_frame(LineHistory(Level::High, data), 0_ns);
  const SsiFrameFields got = decompose_frame(f, r.word);
  EXPECT_EQ(got.value, 0xABCDEu);
  EXPECT_EQ(got.status, 0b10u);
  EXPECT_TRUE(got.parity_ok);
}

// One 7361 frame (125 kHz, 25 clocks) from a slave sending `value` in `sent`; the raw word.
std::uint32_t read_7361(const SsiFrameFormat& sent, std::uint32_t value) {
  const SsiMaster master(ssi7361_master(false));
  SsiSlaveParams sp;
  sp.format = sent;
  SsiSlave slave(sp, [value](Nanos) { return value; });
  const std::vector<Edge> data = respond(slave, master.clock_schedule(0_ns, 1), 500_us);
  return master.read_frame(LineHistory(Level::High, data), 0_ns).word;
}

TEST(Ssi7361Frames, M17StegmannTwentyBitsAtBitFour) {
  // M-17: 512 turns x 2048 counts -> N = 20 at M = 4 (shift 26-4-20 = 2). Turn 5, count 100:
  // value 5*2048 + 100 = 10,340; raw = 10,340 << 2 = 41,360.
  const SsiFrameFormat f = ssi7361_frame(4, 20);
  const std::uint32_t raw = read_7361(f, 10'340);
  EXPECT_EQ(raw, 41'360u);
  const std::uint32_t v = decompose_frame(f, raw).value;
  EXPECT_EQ(v >> 11, 5u);
  EXPECT_EQ(v & 2047u, 100u);
}

TEST(Ssi7361Frames, M19bSubFieldWrap) {
  // M-19 case b: an 8-bit value in stream bits 18..25 read by a 7361 set to M = 19, N = 7:
  // 127 -> 127, 128 (10000000b) -> 0.
  const SsiFrameFormat sent = ssi7361_frame(18, 8);
  const SsiFrameFormat read = ssi7361_frame(19, 7);
  EXPECT_EQ(read_7361(sent, 127), 127u);
  EXPECT_EQ(decompose_frame(read, read_7361(sent, 127)).value, 127u);
  EXPECT_EQ(read_7361(sent, 128), 128u);
  EXPECT_EQ(decompose_frame(read, read_7361(sent, 128)).value, 0u);
}

TEST(Ssi7361Frames, GrayTwelveBitEncoderInATwentyFiveBitFrame) {
  // 12-bit Gray single-turn encoder at M = 1: 2048 (half a turn) is Gray 0xC00, sent in
  // stream bits 1..12 -> raw 0xC00 << 13 = 0x1800000.
  const SsiFrameFormat f = ssi7361_frame(1, 12, SsiCode::Gray);
  const std::uint32_t raw = read_7361(f, 2048);
  EXPECT_EQ(raw, 0x0180'0000u);
  EXPECT_EQ(decompose_frame(f, raw).value, 2048u);
}

TEST(SsiSlaveTiming, LatchAtFirstFallingEdgeShiftOnRisingReleaseAfterMonoflop) {
  // 4-bit frame 1010b at 125 kHz, TM 16 us: DATA drops at F1 (0), bit 1 = 1 at R1 (4 us),
  // bit 2 = 0 at R2 (12 us), bit 3 = 1 at R3 (20 us), bit 4 = 0 at R4 (28 us), and DATA
  // returns high TM after R4, at 44 us.
  SsiMasterParams mp;
  mp.frame_bits = 4;
  mp.frame_period = 100_us;
  const SsiMaster master(mp);
  SsiSlaveParams sp;
  sp.format.frame_bits = 4;
  sp.format.data_bits = 4;
  std::vector<Nanos> latched_at;
  SsiSlave slave(sp, [&](Nanos t) {
    latched_at.push_back(t);
    return 0b1010u;
  });
  const std::vector<Edge> data = respond(slave, master.clock_schedule(0_ns, 1), 100_us);
  const std::vector<Edge> expected = {{0_us, Level::Low},   {4_us, Level::High}, {12_us, Level::Low},
                                      {20_us, Level::High}, {28_us, Level::Low}, {44_us, Level::High}};
  EXPECT_EQ(data, expected);
  ASSERT_EQ(latched_at.size(), 1u);
  EXPECT_EQ(latched_at[0], 0_ns);
  EXPECT_FALSE(slave.busy());
}

TEST(SsiSlaveTiming, MonoflopDeadlineAndAdvance) {
  SsiSlaveParams sp;
  sp.format.frame_bits = 2;
  sp.format.data_bits = 2;
  sp.monoflop = 20_us;
  SsiSlave slave(sp, [](Nanos) { return 0b11u; });
  EXPECT_EQ(slave.deadline(), Nanos::max());
  (void)slave.on_clock({0_us, Level::Low});
  (void)slave.on_clock({4_us, Level::High});
  EXPECT_EQ(slave.deadline(), 24_us);
  EXPECT_FALSE(slave.advance_to(23_us).has_value());
  // Bit 2 = 1 keeps DATA high already, so the expiry needs no edge; the slave is idle again.
  (void)slave.on_clock({8_us, Level::Low});
  (void)slave.on_clock({12_us, Level::High});
  EXPECT_EQ(slave.deadline(), 32_us);
  EXPECT_FALSE(slave.advance_to(40_us).has_value());
  EXPECT_FALSE(slave.busy());
  EXPECT_EQ(slave.data(), Level::High);
}

TEST(SsiSlaveTiming, PreviousFrameEndLatchSendsTheValueFromTheLastExpiry) {
  // L1085-1086: some transducers latch at the end of the previous interrogation. The first
  // frame has nothing stored, so it latches at F1; later frames send the value sampled at
  // the previous monoflop expiry.
  SsiMasterParams mp;
  mp.frame_bits = 8;
  mp.frame_period = 100_us;
  const SsiMaster master(mp);
  SsiSlaveParams sp;
  sp.format.frame_bits = 8;
  sp.format.data_bits = 8;
  sp.latch = SsiLatch::PreviousFrameEnd;
  // Value = time in microseconds; the frame-0 burst ends with R8 at 60 us, expiry at 76 us.
  SsiSlave slave(sp, [](Nanos t) { return static_cast<std::uint32_t>(t.count() / 1000); });
  const std::vector<Edge> data = respond(slave, master.clock_schedule(0_ns, 2), 200_us);
  const auto r = master.read_frames(LineHistory(Level::High, data), 0_ns, 2);
  EXPECT_EQ(r[0].word, 0u);
  EXPECT_EQ(r[1].word, 76u);
}

} // namespace
} // namespace hilrig::signals
