// Modes 5 and 6: each input's active time (digest §3.5) and the counts while it is active
// (§3.6); no cycle, no handshake, written as soon as measured.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// §3.5: Start active 2,500 us -> words 1/2 = 2/500; Latch active 12,345 us (W3) -> words
// 3/4 = 12/345 (A22: 1 = Start, 2 = Latch). Written at the inactive edge + 100 us (the
// mode 5 throughput, L49); status bit 0 stays 0 (L87).
TEST(Amci4501Mode5, ActiveTimeOfEachInput) {
  Bench b;
  b.program_mode(5);
  b.start_pulse(us(1000), us(2500));
  b.latch_pulse(us(2000), us(12345));
  b.run_until(us(3500) + us(99));
  EXPECT_EQ(b.word(2), 0);
  b.run_until(us(3500) + us(100));
  EXPECT_EQ(b.word(1), 2);
  EXPECT_EQ(b.word(2), 500);
  b.run_until(us(14345) + us(100));
  EXPECT_EQ(b.word(3), 12);
  EXPECT_EQ(b.word(4), 345);
  EXPECT_FALSE(b.bit(status::kNewValue));
  EXPECT_TRUE(b.bit(mode_status_bit(5)));
}

// L49, L120: each new value overwrites the old; when the inputs stop the last one stays.
// W8: a 10 kHz train (100 us period, 50 us active) reads 0/50 after every pulse.
TEST(Amci4501Mode5, PulseTrainAndLastValueStays) {
  Bench b;
  b.program_mode(5);
  b.play_start(signals::DiscreteSignal{}.pulse_train(us(1000), us(100), us(50), 20));
  b.latch_pulse(us(500), us(70));
  b.run_until(us(3000));
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 50);
  EXPECT_EQ(b.word(4), 70);
  b.run_until(1_s);
  EXPECT_EQ(b.word(2), 50);
  EXPECT_EQ(b.word(4), 70);
}

// W20 (L237): with JP6 on pins 3-4, active = de-energized: the Start line idles high and
// a 400 us low pulse measures 400 us.
TEST(Amci4501Mode5, FallingJumperMeasuresTheLowTime) {
  Params p;
  p.start_jumper = Jumper::Falling;
  Bench b{p, Level::High, Level::Low};
  b.program_mode(5);
  b.play_start(signals::DiscreteSignal{Level::High}.pulse(us(1000), us(400), Level::Low));
  b.run_until(5_ms);
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 400);
}

// [I] §3.5: an input already active when the mode begins gives no measurement for that
// pulse (its active edge was not seen).
TEST(Amci4501Mode5, PulseActiveAtModeEntryIsNotMeasured) {
  Bench b;
  b.start_at(us(500), Level::High);
  b.run_until(1_ms);
  b.program_mode(5);
  b.start_at(us(2000), Level::Low);
  b.run_until(5_ms);
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 0);
}

// §3.6: counts while each input is active, signed: Start on, F(300), off -> word 1 = 300;
// Latch on, R(200), off -> word 2 = -200 (0xFF38) (L55, L121).
TEST(Amci4501Mode6, SignedCountsWhileActive) {
  Bench b;
  b.program_mode(6);
  b.start_at(us(1000), Level::High);
  b.burst(300, us(1500), us(10)); // ends 4,490 us
  b.start_at(us(5000), Level::Low);
  b.latch_at(us(6000), Level::High);
  b.burst(-200, us(6500), us(10)); // ends 8,490 us
  b.latch_at(us(9000), Level::Low);
  b.burst(50, us(10000), us(10)); // while neither is active: no effect
  b.run_until(us(5125));
  EXPECT_EQ(b.word(1), 300);
  b.run_until(20_ms);
  EXPECT_EQ(b.word(2), 0xFF38);
  EXPECT_EQ(static_cast<std::int16_t>(b.word(2)), -200);
  EXPECT_EQ(b.word(1), 300);
  EXPECT_FALSE(b.bit(status::kNewValue));
  EXPECT_TRUE(b.cycle_edges.empty());
}

// W19 (L117): mode 6 counts up to 32,767.
TEST(Amci4501Mode6, MaximumCount) {
  Bench b;
  b.program_mode(6);
  b.start_at(us(500), Level::High);
  b.burst(32767, us(1000), us(4));
  b.start_at(us(133000), Level::Low);
  b.run_until(135_ms);
  EXPECT_EQ(b.word(1), 32767);
  EXPECT_EQ(b.module->count_overflows(), 0u);
}

// "The count measurement values in mode 6 have a maximum value of 32,767" (L117): one count
// more forward reads 32,767, not -32,768 against its direction (L55, A leads B: positive), and
// far more still 32,767; on the Latch word too. A reverse count stops at -32,768, the word's
// least (A24 [MODEL]). Each beyond the word counts as an overflow.
TEST(Amci4501Mode6, CountsBeyondTheMaximumReadTheMaximum) {
  struct Case {
    int counts;
    std::int16_t reads;
    std::uint64_t overflows;
  };
  for (const Case c : {Case{32767, 32767, 0}, Case{32768, 32767, 1}, Case{33000, 32767, 1},
                       Case{40000, 32767, 1}, Case{-32768, -32768, 0}, Case{-32769, -32768, 1}}) {
    SCOPED_TRACE(c.counts);
    Bench b;
    b.program_mode(6);
    b.latch_at(us(500), Level::High);
    b.burst(c.counts, us(1000), us(4)); // at most 160 ms
    b.latch_at(us(170000), Level::Low);
    b.run_until(172_ms);
    EXPECT_EQ(static_cast<std::int16_t>(b.word(2)), c.reads);
    EXPECT_EQ(b.module->count_overflows(), c.overflows);
  }
}

// A Time Out set in mode 1 survives a change to mode 5: only control bit 1 clears it ("This
// error must be cleared using the Clear Measurement Error bit", L93, L154; a programming
// cycle resets the Command and Parameter errors only, L118), and until then the input words
// are not updated (L119) [MODEL: the manual does not name a mode change; README]. Timeout
// 2 ms, Start at 1 ms: Time Out at 3 ms. Mode 5 at 5 ms: status = bit 11 + bit 6 = 0x0840.
// Start active 1,000 us at 10 ms is not written; cleared at 15 ms, Start active 2,500 us at
// 20 ms -> words 1/2 = 2/500 at 22.5 ms + 100 us (L49, L116).
TEST(Amci4501Mode5, TimeoutFromModeOneBlocksWritesUntilCleared) {
  Bench b;
  b.program_mode(1, 2);
  b.start_pulse(1_ms, us(100));
  b.start_pulse(10_ms, 1_ms);
  b.latch_pulse(us(10500), us(300));
  b.start_pulse(20_ms, us(2500));
  b.run_until(3_ms);
  ASSERT_TRUE(b.bit(status::kTimeout));
  b.run_until(5_ms);
  b.program_mode(5);
  EXPECT_EQ(b.status(), 0x0840);
  b.run_until(15_ms);
  for (std::size_t w = 1; w < 8; ++w) EXPECT_EQ(b.word(w), 0) << "word " << w;
  b.module->write_output(0, control::kClearError);
  EXPECT_EQ(b.status(), 0x0800);
  b.run_until(us(22600) - 1_ns);
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 0);
  b.run_until(us(22600));
  EXPECT_EQ(b.word(1), 2);
  EXPECT_EQ(b.word(2), 500);
}

// The same after mode 4's timeout report (L97-102): S1 at 1 ms, L1 at 3.5 ms (TM1 =
// 2,500 us), timeout 10 ms -> words 2/500/0/0 at 11 ms. Changing to mode 5 keeps Time Out and
// the report (L119); a Latch active 1,000 us at 15 ms is not written; after the clear at
// 18 ms a Latch active 1,500 us at 20 ms gives words 3/4 = 1/500 at 21.5 ms + 100 us.
TEST(Amci4501Mode5, ModeFourTimeoutReportStaysAcrossAModeChange) {
  Bench b;
  b.program_mode(4, 10);
  b.start_pulse(1_ms, us(200));
  b.latch_pulse(us(3500), us(200));
  b.latch_pulse(15_ms, 1_ms);
  b.latch_pulse(20_ms, us(1500));
  b.run_until(11_ms);
  ASSERT_TRUE(b.bit(status::kTimeout));
  b.run_until(12_ms);
  b.program_mode(5);
  EXPECT_EQ(b.status(), 0x0840);
  b.run_until(18_ms);
  EXPECT_EQ(b.word(1), 2);
  EXPECT_EQ(b.word(2), 500);
  EXPECT_EQ(b.word(3), 0);
  EXPECT_EQ(b.word(4), 0);
  b.module->write_output(0, control::kClearError);
  b.run_until(us(21600) - 1_ns);
  EXPECT_EQ(b.word(3), 0);
  b.run_until(us(21600));
  EXPECT_EQ(b.word(3), 1);
  EXPECT_EQ(b.word(4), 500);
  EXPECT_EQ(b.word(1), 2);
}

} // namespace
} // namespace hilrig::models::amci4501::test
