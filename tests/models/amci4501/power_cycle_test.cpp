// A power cycle of the 4501: "The module does not contain a non volatile memory and will
// always power up operating in mode 1" (seeds/001_8422c5eec3a3e376.txt:176; setup storage
// "None", L255). Mode 1 shows as status bits 8-12 all 0 (L85-110, digest §5.2). [MODEL]
// choices the manual leaves open: while off the Cycle Output is off, inputs are not seen, the
// input words read 0; after power-up the count starts at 0 and every status flag is clear.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

constexpr std::uint16_t kModeBits = 0x1F00;

TEST(Amci4501PowerCycle, PowersUpInModeOneWithTheConfigurationGone) {
  Bench b;
  b.run_until(1_ms);
  b.program_mode(3);
  ASSERT_EQ(b.status() & kModeBits, mode_status_bit(3));
  b.burst(100, us(2000), us(10));
  b.run_until(5_ms);
  ASSERT_EQ(b.module->position(), 100);
  b.module->power_off();
  b.run_until(6_ms);
  b.module->power_on();
  EXPECT_EQ(b.status() & kModeBits, 0);
  EXPECT_EQ(b.module->mode(), 1);
  EXPECT_EQ(b.module->position(), 0);
  // The startup routine has to configure the mode again (L176), and it takes.
  b.program_mode(3);
  EXPECT_EQ(b.status() & kModeBits, mode_status_bit(3));
}

TEST(Amci4501PowerCycle, ErrorsAreGoneAfterPowerUp) {
  Bench b;
  b.run_until(1_ms);
  b.program(control::kMode2 | control::kMode3); // two mode bits: Command Error (L91)
  ASSERT_TRUE(b.bit(status::kCommandError));
  b.module->power_off();
  b.run_until(2_ms);
  b.module->power_on();
  EXPECT_EQ(b.status(), 0);
}

TEST(Amci4501PowerCycle, WhileOffTheCycleOutputIsOffAndNothingIsSeen) {
  Bench b;
  b.start_pulse(us(1000), us(5000)); // mode 1: Cycle Output on from Start (L7, L212)
  b.run_until(2_ms);
  ASSERT_TRUE(b.module->cycle_output_on());
  b.module->power_off();
  EXPECT_FALSE(b.module->cycle_output_on());
  ASSERT_FALSE(b.cycle_edges.empty());
  EXPECT_EQ(b.cycle_edges.back().time, 2_ms);
  EXPECT_FALSE(b.cycle_edges.back().on);
  b.burst(50, us(3000), us(10));
  b.run_until(5_ms);
  EXPECT_EQ(b.module->position(), 0);
  for (const std::uint16_t w : b.module->input_words()) EXPECT_EQ(w, 0);
  // The Start input is still active (until 6 ms) at power-up: its mark comes from its level.
  b.module->power_on();
  EXPECT_TRUE(b.bit(status::kStartMark));
  b.run_until(10_ms);
  EXPECT_FALSE(b.module->cycle_output_on()); // a level at power-up is no Start edge
}

// [MODEL] The velocity timer starts with the module: the word counts whole 50 ms windows from
// power-up (L114), not the rest of the window the module was in when it went off. Edges every
// 10 us (100,000 counts/s) from 5 us on; off at 20 ms, on at 25 ms: (25, 75] ms holds 5,000
// edges, refreshed at 75 ms, and 0 (power-up cleared it, L176) until then.
TEST(Amci4501PowerCycle, TheVelocityWindowStartsAtPowerUp) {
  Bench b;
  b.burst(20000, us(5), us(10));
  b.run_until(20_ms);
  b.module->power_off();
  b.run_until(25_ms);
  b.module->power_on();
  b.run_until(75_ms - 1_ns);
  EXPECT_EQ(b.word(2), 0); // the 50 ms refresh of the old grid is gone
  b.run_until(75_ms);
  EXPECT_EQ(b.word(2), 5000);
  b.run_until(125_ms);
  EXPECT_EQ(b.word(2), 5000);
}

} // namespace
} // namespace hilrig::models::amci4501::test
