// `hilrig synth ssi`: run in-process, read the VCD back and check the 7361's clock and the
// transducer's data line against values worked out by hand from ssi7361.md §2.1: clock idles
// high, F_j = F1 + (j-1)T, R_k = F1 + (k-1/2)T, 25 clocks; bit k read at F1 + kT; TINT 500 us
// at 125 kHz and 250 us at 500 kHz; DATA back high TM after the last clock edge.

#include <gtest/gtest.h>

#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "tests/signals/run_synth.hpp"
#include "tests/tools/vcd_reader.hpp"

using namespace hilrig;

namespace {

using test::synth;

std::vector<long long> edges(const test::Vcd& vcd, const std::string& name, std::uint64_t level) {
  std::vector<long long> out;
  for (const test::VcdChange& c : vcd.leaf(name).changes)
    if (c.bits() == level) out.push_back(c.time);
  return out;
}

// Reads the data line as the 7361 does: bit k at F1 + k*T, MSB first, 25 bits.
std::uint32_t read_word(const test::Vcd& vcd, long long f1, long long period) {
  std::uint32_t word = 0;
  for (long long k = 1; k <= 25; ++k)
    word = (word << 1) | static_cast<std::uint32_t>(vcd.leaf("data").bits_at(f1 + k * period));
  return word;
}

} // namespace

TEST(SynthSsi, ClockAt125kHzIs25BitsIn192us) {
  const std::string out = test::kSynthDir + "/synth_ssi_125.vcd";
  synth({"ssi", "--out", out, "--frames", "2", "--first", "20us"});
  const test::Vcd vcd = test::read_vcd_file(out);
  EXPECT_EQ(vcd.leaf("clock").initial.value().bits(), 1u); // idles high
  const auto falling = edges(vcd, "clock", 0);
  const auto rising = edges(vcd, "clock", 1);
  ASSERT_EQ(falling.size(), 50u);
  ASSERT_EQ(rising.size(), 50u);
  // T = 8 us: first to last falling edge of a frame 24 * 8 = 192 us; R1 half a period after F1.
  EXPECT_EQ(falling[0], 20'000);
  EXPECT_EQ(falling[24] - falling[0], 192'000);
  EXPECT_EQ(rising[0], 24'000);
  EXPECT_EQ(rising[24], 20'000 + 196'000);
  // TINT 500 us: the second frame's F1.
  EXPECT_EQ(falling[25], 520'000);
}

TEST(SynthSsi, ClockAt500kHzIs25BitsIn48us) {
  const std::string out = test::kSynthDir + "/synth_ssi_500.vcd";
  synth({"ssi", "--out", out, "--clock-khz", "500", "--frames", "3", "--first", "10us"});
  const test::Vcd vcd = test::read_vcd_file(out);
  const auto falling = edges(vcd, "clock", 0);
  ASSERT_EQ(falling.size(), 75u);
  // T = 2 us: 24 * 2 = 48 us; TINT 250 us.
  for (std::size_t f = 0; f < 3; ++f) {
    EXPECT_EQ(falling[25 * f], 10'000 + 250'000 * static_cast<long long>(f));
    EXPECT_EQ(falling[25 * f + 24] - falling[25 * f], 48'000);
  }
}

TEST(SynthSsi, BinaryAndGrayWordsOfAQuarterTurn) {
  // 0.25 turn at 4096 counts/turn = 1024. Data field N = 24 at M = 1, stream bit 25 unused (0):
  // binary word 1024 << 1 = 2048; Gray(1024) = 1024 ^ 512 = 1536, word 3072. Either decodes to 1024.
  for (const bool gray : {false, true}) {
    const std::string out = test::kSynthDir + (gray ? "/synth_ssi_gray.vcd" : "/synth_ssi_bin.vcd");
    std::vector<std::string> args{"ssi", "--out", out, "--frames", "2", "--start", "0.25"};
    if (gray) args.emplace_back("--gray");
    synth(args);
    const test::Vcd vcd = test::read_vcd_file(out);
    const std::uint32_t expected = gray ? 3072u : 2048u;
    EXPECT_EQ(read_word(vcd, 20'000, 8'000), expected);
    EXPECT_EQ(read_word(vcd, 520'000, 8'000), expected);
    const auto& words = vcd.leaf("word").changes;
    const auto& values = vcd.leaf("value").changes;
    ASSERT_EQ(words.size(), 2u);
    ASSERT_EQ(values.size(), 2u);
    // The word appears when bit 25 is read: F1 + 25 * 8 us.
    EXPECT_EQ(words[0].time, 20'000 + 200'000);
    EXPECT_EQ(words[0].bits(), expected);
    EXPECT_EQ(values[0].bits(), 1024u);
    EXPECT_EQ(values[1].bits(), 1024u);
    // DATA drops at F1, holds bit 25 (unused: 0) after R25 (F1 + 196 us), and returns high
    // TM = 16 us after it.
    EXPECT_EQ(vcd.leaf("data").changes.front().time, 20'000);
    EXPECT_EQ(vcd.leaf("data").bits_at(20'000 + 196'000 + 16'000 - 1), 0u);
    EXPECT_EQ(vcd.leaf("data").bits_at(20'000 + 196'000 + 16'000), 1u);
  }
}

TEST(SynthSsi, TurningShaftIsLatchedAtEachFrame) {
  // 60 rpm = 1 turn/s, 4096 counts/turn: latched at F1 = 20, 520, 1020, 1520 us ->
  // floor(4096 * t) = 0 (0.08), 2 (2.13), 4 (4.18), 6 (6.23).
  const std::string out = test::kSynthDir + "/synth_ssi_turning.vcd";
  synth({"ssi", "--out", out, "--frames", "4", "--rpm", "60"});
  const test::Vcd vcd = test::read_vcd_file(out);
  const auto& values = vcd.leaf("value").changes;
  ASSERT_EQ(values.size(), 4u);
  EXPECT_EQ(values[0].bits(), 0u);
  EXPECT_EQ(values[1].bits(), 2u);
  EXPECT_EQ(values[2].bits(), 4u);
  EXPECT_EQ(values[3].bits(), 6u);
  EXPECT_EQ(read_word(vcd, 1'520'000, 8'000), 6u << 1);
}

TEST(SynthSsi, SlaveFaultsReachTheDecodedWord) {
  const std::string out = test::kSynthDir + "/synth_ssi_fault.vcd";
  // Stream bit 1 (the data MSB, weight 2^24 in the word) inverted on the wire:
  // word 2048 | 2^24, value 1024 + 2^23.
  synth({"ssi", "--out", out, "--frames", "1", "--start", "0.25", "--flip-bit", "1"});
  test::Vcd vcd = test::read_vcd_file(out);
  EXPECT_EQ(vcd.leaf("word").changes.at(0).bits(), 2048u + (1u << 24));
  EXPECT_EQ(vcd.leaf("value").changes.at(0).bits(), 1024u + (1u << 23));
  // Data stuck high: every bit reads 1 (25 ones), the data field all ones.
  synth({"ssi", "--out", out, "--frames", "1", "--start", "0.25", "--stuck", "high"});
  vcd = test::read_vcd_file(out);
  EXPECT_EQ(vcd.leaf("data").initial.value().bits(), 1u);
  EXPECT_EQ(vcd.leaf("data").changes.size(), 0u);
  EXPECT_EQ(vcd.leaf("word").changes.at(0).bits(), (1u << 25) - 1);
  EXPECT_EQ(vcd.leaf("value").changes.at(0).bits(), (1u << 24) - 1);
}

TEST(SynthSsi, LateDataShiftsTheWordByOneBit) {
  // 125 kHz: the 7361 reads bit k at R_k + 4 us. Data that changes 5 us after each rising
  // edge is read one slot late: slot 1 sees the latch level (0), slot k sees bit k-1. The
  // binary word 2048 (0.25 turn at 4096 counts) reads as 1024, the position as 512.
  const std::string out = test::kSynthDir + "/synth_ssi_late.vcd";
  synth({"ssi", "--out", out, "--frames", "1", "--start", "0.25", "--late", "5us"});
  test::Vcd vcd = test::read_vcd_file(out);
  EXPECT_EQ(vcd.leaf("word").changes.at(0).bits(), 1024u);
  EXPECT_EQ(vcd.leaf("value").changes.at(0).bits(), 512u);
  // Data stuck low: the line starts low and every bit reads 0.
  synth({"ssi", "--out", out, "--frames", "1", "--start", "0.25", "--stuck", "low"});
  vcd = test::read_vcd_file(out);
  EXPECT_EQ(vcd.leaf("data").initial.value().bits(), 0u);
  EXPECT_EQ(vcd.leaf("word").changes.at(0).bits(), 0u);
}

// The data field is what the 7361's Format command accepts, nothing more (ssi7361.md §3,
// L2126-2133, L2143-2148, L2162-2163): MSB Number M 1 .. 24, Number of Data Bits N 2 .. 25,
// M + N <= 26; the board raises FMTErr for anything else, so synth refuses it. Every M and N
// the 5-bit fields can hold, against the manual's numbers written out here.
TEST(SynthSsi, FieldIsExactlyWhatThe7361CanBeSetTo) {
  const std::string out = test::kSynthDir + "/synth_ssi_field.vcd";
  for (int m = 0; m <= 31; ++m) {
    for (int n = 0; n <= 31; ++n) {
      const bool board_accepts = m >= 1 && m <= 24 && n >= 2 && n <= 25 && m + n <= 26;
      // 4 counts a turn fit every accepted field (2 bits and up).
      const std::vector<std::string> args{
          "ssi",   "--out",           out,      "--frames",        "1",
          "--msb", std::to_string(m), "--bits", std::to_string(n), "--counts-per-turn",
          "4"};
      bool accepted = true;
      try {
        synth(args);
      } catch (const std::exception&) {
        accepted = false;
      }
      EXPECT_EQ(accepted, board_accepts) << "--msb " << m << " --bits " << n;
    }
  }
}

// A single-turn position 0 .. counts-per-turn - 1 fits the N-bit field or is refused: 8192
// counts a turn need 13 bits (they once wrapped silently in 12).
TEST(SynthSsi, CountsPerTurnFitTheField) {
  const std::string out = test::kSynthDir + "/synth_ssi_cpt.vcd";
  const auto accepted = [&](const std::string& bits, const std::string& cpt) {
    try {
      synth({"ssi", "--out", out, "--frames", "1", "--bits", bits, "--counts-per-turn", cpt});
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  EXPECT_TRUE(accepted("12", "4096"));
  EXPECT_FALSE(accepted("12", "4097"));
  EXPECT_FALSE(accepted("12", "8192"));
  EXPECT_TRUE(accepted("13", "8192"));
  EXPECT_TRUE(accepted("2", "4"));
  EXPECT_FALSE(accepted("2", "5"));
  EXPECT_TRUE(accepted("25", "33554432"));
  EXPECT_FALSE(accepted("25", "33554433"));
}

// --monoflop takes the range `[ssi] monoflop` takes, with its own clock's half period: longer
// than T/2 (T = 8 us at 125 kHz, 2 us at 500 kHz, 7361 manual L1123; retriggered by every clock
// edge, T/2 apart, a shorter TM returns DATA to idle inside a frame), at most 1 ms (TM
// "typically 12 to 20 uS", L1091-1092), and it must run out before the next frame: TM after a
// frame's last rising edge R25 (24.5 periods after F1: 196 us at 125 kHz, 49 us at 500 kHz) DATA
// returns to idle, and the transducer must be ready within the idle time before the next F1
// (L1089-1093; TINT 500 / 250 us, L1097-1098): TM < 304 us at 125 kHz, < 201 us at 500 kHz.
TEST(SynthSsi, MonoflopIsAboveHalfAClockPeriodAndFitsTheIdleGap) {
  const std::string out = test::kSynthDir + "/synth_ssi_monoflop.vcd";
  const auto accepted = [&](const std::string& khz, const std::string& tm) {
    try {
      synth({"ssi", "--out", out, "--frames", "2", "--clock-khz", khz, "--monoflop", tm});
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  EXPECT_FALSE(accepted("125", "0s"));
  EXPECT_FALSE(accepted("125", "3999ns"));
  EXPECT_FALSE(accepted("125", "4us"));
  EXPECT_TRUE(accepted("125", "4001ns"));
  EXPECT_FALSE(accepted("500", "999ns"));
  EXPECT_FALSE(accepted("500", "1us"));
  EXPECT_TRUE(accepted("500", "1001ns"));
  EXPECT_TRUE(accepted("125", "16us"));
  EXPECT_TRUE(accepted("125", "303999ns"));
  EXPECT_FALSE(accepted("125", "304us"));
  EXPECT_FALSE(accepted("125", "304001ns"));
  EXPECT_TRUE(accepted("500", "200999ns"));
  EXPECT_FALSE(accepted("500", "201us"));
  EXPECT_FALSE(accepted("500", "201001ns"));
  EXPECT_FALSE(accepted("125", "1000001ns")); // beyond the campaign's 1 ms too
}
