// Limit windows, output allocation and the output mask (pls2700.md §4.4, §4.5, §4.7, §4.8;
// examples W4, W6, W7, W8, W12, W14), programmed by host words and read on the output pins.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

// Output `output` at machine position `mp` (shaft held at the count centre, SF 360).
bool on_at(Bench& b, int output, int mp, int sf = 360) {
  b.hold(1, mp, sf);
  b.run_for(1_ms);
  return b.pin(output);
}

TEST(Pls2700Limits, W4SingleWindowOnFromOnUpToOff) {
  // W4 (L407-L409): ON 230 / OFF 270: 229 off, 230 on, 269 on, 270 off.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0xC011, 0x0000, 0x0230, 0x0270}), error::kNone);
  EXPECT_FALSE(on_at(b, 1, 229));
  EXPECT_TRUE(on_at(b, 1, 230));
  EXPECT_EQ(b.btr()[2] & 0xFF, 0x01); // status low byte, bit 0 = output 1
  EXPECT_TRUE(on_at(b, 1, 269));
  EXPECT_FALSE(on_at(b, 1, 270));
}

TEST(Pls2700Limits, W7TwoWindowsOnOutput6) {
  // W7 (L1002-L1050): output 6 on for MP in [45, 140) and [240, 320).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0xC062, 0x0000, 0x0045, 0x0140, 0x0240, 0x0320}), error::kNone);
  const std::vector<std::pair<int, bool>> expected{{44, false},  {45, true},  {139, true}, {140, false},
                                                   {239, false}, {240, true}, {319, true}, {320, false}};
  for (const auto& [mp, on] : expected) {
    EXPECT_EQ(on_at(b, 6, mp), on) << "MP " << mp;
  }
  // On a 2731/2741 output 6 has no advances: AAAAh must be 0000h (L1399) -> E6h for 1005h.
  EXPECT_EQ(b.btw({0x8400}), error::kNone);
  EXPECT_EQ(b.btw({0xC062, 0x1005, 0x0045, 0x0140, 0x0240, 0x0320}), 0xE6);
}

TEST(Pls2700Limits, W14SampleProgramBtw) {
  // W14 (L1464, L1476): N10:20..26 = -31744, -30719, 864, -16367, 0, 16, 32 as PLC INTs are
  // 8400h 8801h 0360h C011h 0000h 0010h 0020h: Clear Errors, SF 360, output 1 on 10..19.
  const std::vector<std::int16_t> plc{-31744, -30719, 864, -16367, 0, 16, 32};
  std::vector<std::uint16_t> words;
  for (std::int16_t v : plc) {
    words.push_back(static_cast<std::uint16_t>(v));
  }
  EXPECT_EQ(words, (std::vector<std::uint16_t>{0x8400, 0x8801, 0x0360, 0xC011, 0x0000, 0x0010, 0x0020}));
  Bench b(ModelVariant::M2731);
  EXPECT_EQ(b.device().write_btw(words), error::kNone);
  EXPECT_FALSE(on_at(b, 1, 9));
  EXPECT_TRUE(on_at(b, 1, 10));
  EXPECT_TRUE(on_at(b, 1, 19));
  EXPECT_FALSE(on_at(b, 1, 20));
  EXPECT_FALSE(on_at(b, 1, 155)); // W15: 155 is outside [10, 20)
  EXPECT_EQ(b.btr()[2], 0);
}

TEST(Pls2700Limits, WrapPairAndEqualPair) {
  // R-LS-3 [I]: 350/10 on for 350..359 and 0..9. R-LS-4 [I]: 100/100 never on.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0xC011, 0x0000, 0x0350, 0x0010, 0xC021, 0x0000, 0x0100, 0x0100}), error::kNone);
  EXPECT_FALSE(on_at(b, 1, 349));
  EXPECT_TRUE(on_at(b, 1, 350));
  EXPECT_TRUE(on_at(b, 1, 359));
  EXPECT_TRUE(on_at(b, 1, 0));
  EXPECT_TRUE(on_at(b, 1, 9));
  EXPECT_FALSE(on_at(b, 1, 10));
  EXPECT_FALSE(on_at(b, 2, 100));
  // The switchable readings: no wrap, and ON == OFF as a full turn.
  Params p;
  p.wrap_pairs = false;
  p.equal_pair_full_turn = true;
  Bench alt(ModelVariant::M2741, p);
  EXPECT_EQ(alt.btw({0xC011, 0x0000, 0x0350, 0x0010, 0xC021, 0x0000, 0x0100, 0x0100}), error::kNone);
  EXPECT_FALSE(on_at(alt, 1, 355));
  EXPECT_TRUE(on_at(alt, 2, 7));
}

TEST(Pls2700Limits, W8DeletingAnOverlappingPairLeavesAGap) {
  // W8 (L1074): pairs 10-50 and 20-30; deleting 20-30 leaves [10,20) u [30,50) until 10-50
  // is entered again or power is cycled.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0xC022, 0x0000, 0x0010, 0x0050, 0x0020, 0x0030}), error::kNone);
  EXPECT_TRUE(on_at(b, 2, 25));
  EXPECT_TRUE(b.device().keyboard_delete_pair(2, 2));
  EXPECT_TRUE(on_at(b, 2, 19));
  EXPECT_FALSE(on_at(b, 2, 20));
  EXPECT_FALSE(on_at(b, 2, 29));
  EXPECT_TRUE(on_at(b, 2, 30));
  EXPECT_TRUE(on_at(b, 2, 49));
  b.device().power_cycle();
  EXPECT_TRUE(on_at(b, 2, 25));
  // Re-entering the pair (host) also restores it.
  EXPECT_EQ(b.btw({0xC022, 0x0000, 0x0010, 0x0050, 0x0020, 0x0030}), error::kNone);
  EXPECT_TRUE(b.device().keyboard_delete_pair(2, 2));
  EXPECT_FALSE(on_at(b, 2, 25));
  EXPECT_EQ(b.btw({0xC021, 0x0000, 0x0010, 0x0050}), error::kNone);
  EXPECT_TRUE(on_at(b, 2, 25));
}

TEST(Pls2700Limits, W8CompanionDeletingTheUpperOverlap) {
  // W8 derived: 10-50 and 40-60 (union [10,60)); delete 40-60 -> on only [10,40) until a
  // power cycle, then [10,50).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0xC032, 0x0000, 0x0010, 0x0050, 0x0040, 0x0060}), error::kNone);
  EXPECT_TRUE(on_at(b, 3, 55));
  EXPECT_TRUE(b.device().keyboard_delete_pair(3, 2));
  EXPECT_TRUE(on_at(b, 3, 39));
  EXPECT_FALSE(on_at(b, 3, 40));
  EXPECT_FALSE(on_at(b, 3, 55));
  b.device().power_cycle();
  EXPECT_TRUE(on_at(b, 3, 45));
  EXPECT_FALSE(on_at(b, 3, 50));
}

// Programs outputs 1..8 with the window 10..19 each.
void all_outputs_10_to_20(Bench& b) {
  for (std::uint16_t n = 1; n <= 8; ++n) {
    ASSERT_EQ(b.btw({static_cast<std::uint16_t>(0xC001 | (n << 4)), 0x0000, 0x0010, 0x0020}), error::kNone);
  }
}

TEST(Pls2700Allocation, W6OutputAllocationSplitsOutputsBetweenChannels) {
  // W6 (L394-L397): OA 8 -> 1-8 on ch1; 6 -> 1-6 ch1, 7-8 ch2; 0 -> 1-8 ch2. OA is the high
  // byte of channel 1's TR word (R-OA-3). Ch1 at 15 (inside 10..19), ch2 at 100 (outside).
  Bench b(ModelVariant::M2742);
  b.hold(1, 15, 360);
  b.hold(2, 100, 360);
  all_outputs_10_to_20(b);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().output_states(), 0xFF); // default OA 8
  EXPECT_EQ(b.btw({0x8804, 0x0603}), error::kNone);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().output_states(), 0x3F);
  EXPECT_EQ(b.device().owner(6), 1);
  EXPECT_EQ(b.device().owner(7), 2);
  EXPECT_EQ(b.btw({0x8804, 0x0003}), error::kNone);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().output_states(), 0x00);
  b.hold(2, 12, 360);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().output_states(), 0xFF);
  EXPECT_EQ(b.btr()[4] & 0xFF, 0xFF);
}

TEST(Pls2700Allocation, W12BothTransducerSetup) {
  // W12 (L1385): A807h 0360h 0720h 0090h 0600h 0402h 0001h -> ch1 SF 360 CO 90 OA 4 TR 2;
  // ch2 SF 720 CO 600 TR 1; error 00h.
  Bench b(ModelVariant::M2742);
  b.hold(1, 0, 360);
  b.hold(2, 0, 720);
  EXPECT_EQ(b.btw({0xA807, 0x0360, 0x0720, 0x0090, 0x0600, 0x0402, 0x0001}), error::kNone);
  const pls2700::Setup& s = b.device().setup();
  EXPECT_EQ(s.channels[0].scale_factor, 360);
  EXPECT_EQ(s.channels[0].circular_offset, 90);
  EXPECT_EQ(s.channels[0].tach_code, 2);
  EXPECT_EQ(s.output_allocation, 4);
  EXPECT_EQ(s.channels[1].scale_factor, 720);
  EXPECT_EQ(s.channels[1].circular_offset, 600);
  EXPECT_EQ(s.channels[1].tach_code, 1);
  EXPECT_EQ(b.device().owner(4), 1);
  EXPECT_EQ(b.device().owner(5), 2);
  b.run_for(1_ms);
  EXPECT_EQ(b.btr()[0], 90);  // (0 + 90) mod 360
  EXPECT_EQ(b.btr()[2], 600); // (0 + 600) mod 720
}

TEST(Pls2700Mask, MaskForcesOutputsOffAndStatusShowsThePins) {
  // R-M-1 (L1358): 83MMh, bit 0 = output 1; 0 = forced off. Power-up FFh (R-M-2 [I]);
  // status shows the masked state (R-M-3 [I]).
  Bench b(ModelVariant::M2741);
  all_outputs_10_to_20(b);
  b.hold(1, 15, 360);
  b.run_for(1_ms);
  EXPECT_EQ(b.device().setup().mask, 0xFF);
  EXPECT_EQ(b.device().output_states(), 0xFF);
  EXPECT_EQ(b.btw({0x83A5}), error::kNone);
  b.run_for(1_ms);
  EXPECT_EQ(b.btr()[2] & 0xFF, 0xA5);
  for (int n = 1; n <= 8; ++n) {
    EXPECT_EQ(b.pin(n), ((0xA5 >> (n - 1)) & 1) != 0) << "output " << n;
  }
}

} // namespace
} // namespace hilrig::models::pls2700
