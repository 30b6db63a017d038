// The Series 2700's power cycle (power_off / power_on): nvRAM keeps the parameters, the
// absolute resolver keeps the position, what is not in nvRAM starts again. Manual 940-07090
// (seeds/002_46e90574ec92805f.txt).
#include <gtest/gtest.h>

#include "models/pls2700/error_codes.hpp"
#include "models/pls2700/instructions.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

constexpr std::uint16_t kSf4096 = 0x4096; // BCD

void cycle(Bench& b) {
  b.device().power_off();
  b.run_for(5_ms);
  b.device().power_on();
  b.run_for(2_ms);
}

// L322, L776: "All of the parameters are stored in non-volatile static RAM memory when power is
// removed"; L768 (resolver): the position needs no homing. L1356-1357: the keyboard lock (8100h)
// is kept through power loss, only 8200h undoes it.
TEST(Pls2700PowerCycle, NvramKeepsTheSetupAndTheKeyboardLockAndThePositionIsAbsolute) {
  Bench b(ModelVariant::M2741);
  b.hold(1, 1638, 4096);
  ASSERT_EQ(b.btw({0x8805, kSf4096, 0x0000, 0xC011, 0x1005, 0x1000, 0x3000, kDisableKeyboard}), error::kNone);
  b.run_for(2_ms);
  ASSERT_EQ(b.btr()[0], 1638);
  const pls2700::Setup before = b.device().setup();
  cycle(b);
  const OutputSetup& o = b.device().setup().outputs[0];
  EXPECT_EQ(o.pair_count, before.outputs[0].pair_count);
  EXPECT_EQ(o.pairs, before.outputs[0].pairs);
  EXPECT_EQ(o.advance_on_ms, 10);
  EXPECT_EQ(o.advance_off_ms, 5);
  EXPECT_EQ(b.device().setup().channels[0].scale_factor, 4096);
  EXPECT_TRUE(b.device().setup().keyboard_disabled);
  EXPECT_FALSE(b.device().program_mode()); // still locked in Display Mode (L543)
  EXPECT_EQ(b.btr()[0], 1638);
  EXPECT_TRUE(b.pin(1)); // 1000-3000 still programmed
}

// L1074: the OFF space left by deleting an overlapping pair lasts "until ... power is cycled";
// Clear Errors (8400h, L1359) is no remedy.
TEST(Pls2700PowerCycle, TheOffSpaceOfADeletedOverlapSurvivesClearErrorsButNotAPowerCycle) {
  Bench b(ModelVariant::M2741);
  b.hold(1, 25, 360);
  ASSERT_EQ(b.btw({0xC012, 0x0000, 0x0010, 0x0050, 0x0020, 0x0030}), error::kNone);
  b.run_for(2_ms);
  ASSERT_TRUE(b.pin(1));
  ASSERT_TRUE(b.device().keyboard_delete_pair(1, 2));
  b.run_for(2_ms);
  EXPECT_FALSE(b.pin(1));
  EXPECT_EQ(b.btw({kClearErrors}), error::kNone);
  b.run_for(2_ms);
  EXPECT_FALSE(b.pin(1));
  cycle(b);
  EXPECT_TRUE(b.pin(1));
  EXPECT_EQ(b.device().setup().outputs[0].pair_count, 1); // the deletion itself is stored
}

// [MODEL] (R-M-2): the output mask is FFh at power-up; a programming error is not kept.
TEST(Pls2700PowerCycle, TheMaskAndTheErrorByteStartAgain) {
  Bench b(ModelVariant::M2741);
  b.hold(1, 25, 360);
  ASSERT_EQ(b.btw({0xC011, 0x0000, 0x0010, 0x0050, 0x8300}), error::kNone);
  b.run_for(2_ms);
  EXPECT_FALSE(b.pin(1));
  EXPECT_NE(b.btw({0xC091, 0x0000, 0x0010, 0x0050}), error::kNone); // output 9: invalid
  ASSERT_NE(b.device().error_byte(), error::kNone);
  cycle(b);
  EXPECT_EQ(b.device().error_byte(), error::kNone);
  EXPECT_EQ(b.device().setup().mask, 0xFF);
  EXPECT_TRUE(b.pin(1));
}

// [MODEL] while off: outputs off, the host reads 0, a block transfer does nothing.
TEST(Pls2700PowerCycle, WhileOffOutputsAreOffAndTheHostIsNotAnswered) {
  Bench b(ModelVariant::M2741);
  b.hold(1, 25, 360);
  ASSERT_EQ(b.btw({0xC011, 0x0000, 0x0010, 0x0050}), error::kNone);
  b.run_for(2_ms);
  ASSERT_TRUE(b.pin(1));
  b.device().power_off();
  b.run_for(2_ms);
  EXPECT_FALSE(b.pin(1));
  EXPECT_EQ(b.btr(), std::vector<std::uint16_t>(3, 0));
  b.btw({0xC011, 0x0000, 0x0100, 0x0200});
  EXPECT_EQ(b.device().setup().outputs[0].pairs[0].on, 10);
}

} // namespace
} // namespace hilrig::models::pls2700
