// Modes 3 and 4: Start -> Latch times (digest §3.3) and the two-direction timing with its
// filters and firmware-v3 timeout reports (§3.4).
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// W3 (L116): 12,345 us -> upper 12, lower 345. Start at 1,000 us, Latch at 13,345 us.
// Status after the result with both inputs idle: 0x0201 (digest §5.2 [D]).
TEST(Amci4501Mode3, TimeSplitTwelveThreeFortyFive) {
  Bench b;
  b.program_mode(3);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(13345), us(300));
  b.run_until(us(13345) + us(124));
  EXPECT_FALSE(b.bit(status::kNewValue));
  b.run_until(us(13345) + us(125));
  EXPECT_EQ(b.word(1), 12);
  EXPECT_EQ(b.word(2), 345);
  b.run_until(20_ms);
  EXPECT_EQ(b.status(), 0x0201);
  EXPECT_TRUE(b.cycle_edges.empty()) << "the Cycle Output is not used in mode 3";
}

// L26: 1 us resolution: the module counts a 1 us timer, so edges 1,000.4 us and
// 2,000.3 us apart from t = 0 read ticks 1,000 and 2,000: T = 1,000 us -> 1 / 0.
TEST(Amci4501Mode3, OneMicrosecondResolution) {
  Bench b;
  b.program_mode(3);
  b.start_at(Nanos{1'000'400}, Level::High);
  b.latch_at(Nanos{2'000'300}, Level::High);
  b.run_until(5_ms);
  EXPECT_EQ(b.word(1), 1);
  EXPECT_EQ(b.word(2), 0);
}

// W20 (L237): with JP5/JP6 on pins 3-4 the module acts on falling transitions; inputs idle
// high (de-energized = active with the negative setting is the LED's view; here the rig
// holds them energized and drops them). Start falls at 2,000, Latch falls at 2,750 us.
TEST(Amci4501Mode3, FallingEdgeJumpers) {
  Params p;
  p.start_jumper = Jumper::Falling;
  p.latch_jumper = Jumper::Falling;
  Bench b{p, Level::High, Level::High};
  b.program_mode(3);
  b.start_at(us(1000), Level::Low);
  b.start_at(us(1500), Level::High); // rising: inactive edge
  b.start_at(us(2000), Level::Low);  // not a new cycle: one is running
  b.latch_at(us(1800), Level::Low);  // ends the cycle: 800 us
  b.run_until(5_ms);
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 800);
  EXPECT_TRUE(b.bit(status::kStartMark)) << "Start is low = active with pins 3-4";
  EXPECT_TRUE(b.bit(status::kLatchMark));
}

// W5 (L169) in mode 3: a Start with no Latch times out at 10 s when the word is 0.
TEST(Amci4501Mode3, TimeoutZeroIsTenSeconds) {
  Bench b;
  b.program_mode(3, 0);
  b.start_pulse(1_ms, us(200));
  b.run_until(milliseconds(10001) - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.run_until(milliseconds(10001));
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 0);
}

// Property (L26, L116): for random Start/Latch instants (any nanosecond), the time is the
// difference of the 1 us timer's readings, floor(tL / 1 us) - floor(tS / 1 us), split
// div/mod 1000. Fixed seed.
TEST(Amci4501Mode3, PropertyTimerTicksAndSplit) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::int64_t> start_ns(1'000'000, 2'000'000);
  std::uniform_int_distribution<std::int64_t> span_ns(1'000, 900'000'000);
  for (int run = 0; run < 50; ++run) {
    const std::int64_t ts = start_ns(rng);
    const std::int64_t tl = ts + span_ns(rng);
    Bench b;
    b.program_mode(3);
    b.prompt_host(1_ms);
    b.start_at(Nanos{ts}, Level::High);
    b.latch_at(Nanos{tl}, Level::High);
    b.run_until(Nanos{tl} + 1_ms);
    const std::int64_t t_us = tl / 1000 - ts / 1000;
    EXPECT_EQ(b.word(1), t_us / 1000) << ts << " " << tl;
    EXPECT_EQ(b.word(2), t_us % 1000) << ts << " " << tl;
  }
}

// §3.4: S1 at 1,000, L1 at 5,000 (TM1 = 4,000 us), L2 at 7,000, S2 at 10,000 us (TM2 =
// 3,000 us). Words 4/0/3/0, published only after S2 (L32, L228).
TEST(Amci4501Mode4, TwoDirectionTiming) {
  Bench b;
  b.program_mode(4);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(5000), us(300));
  b.latch_pulse(us(7000), us(300));
  b.start_pulse(us(10000), us(300));
  b.run_until(us(9000));
  EXPECT_FALSE(b.bit(status::kNewValue)) << "never after L1 alone";
  b.run_until(us(10125));
  EXPECT_TRUE(b.bit(status::kNewValue));
  EXPECT_EQ(b.word(1), 4);
  EXPECT_EQ(b.word(2), 0);
  EXPECT_EQ(b.word(3), 3);
  EXPECT_EQ(b.word(4), 0);
}

// L32: the input that starts a timing need not be off when the other turns on.
TEST(Amci4501Mode4, OverlappingInputs) {
  Bench b;
  b.program_mode(4);
  b.start_at(us(1000), Level::High);
  b.latch_at(us(2500), Level::High); // TM1 = 1,500 with Start still on
  b.start_at(us(3000), Level::Low);
  b.latch_at(us(3000), Level::Low);
  b.latch_at(us(4000), Level::High); // L2 (1,500 after L1 >= TM1/4 = 375)
  b.start_at(us(6250), Level::High); // S2 with Latch still on: TM2 = 2,250
  b.run_until(10_ms);
  EXPECT_EQ(b.word(1), 1);
  EXPECT_EQ(b.word(2), 500);
  EXPECT_EQ(b.word(3), 2);
  EXPECT_EQ(b.word(4), 250);
}

// W14 (L40): with TM1 = 4,000 us, a second Latch is ignored until TM1/4 = 1,000 us after
// L1. L1 at 5,000; a Latch at 5,999 is ignored; the one at 6,000 is L2; S2 at 9,000:
// TM2 = 3,000 (it would be 3,001 had 5,999 been taken).
TEST(Amci4501Mode4, FilterOneIgnoresEarlySecondLatch) {
  Bench b;
  b.program_mode(4);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(5000), us(300));
  b.latch_at(us(5999), Level::High);
  b.latch_at(us(5999) + Nanos{500}, Level::Low);
  b.latch_pulse(us(6000), us(300));
  b.start_pulse(us(9000), us(300));
  b.run_until(12_ms);
  EXPECT_EQ(b.word(3), 3);
  EXPECT_EQ(b.word(4), 0);
}

// W15 (L42): the next cycle's Start is ignored until max(T3, 5 ms) after S2 ([I] A18:
// T3 = TM2). Cycle 1 has TM2 = 3 ms (-> 5 ms hold), ending at S2 = 10,000 us. A Start at
// 14,999 us is ignored; the one at 15,000 us is S1. Then L1 at 17,000 -> TM1 = 2,000 us.
TEST(Amci4501Mode4, FilterTwoHoldsFiveMilliseconds) {
  Bench b;
  b.program_mode(4);
  b.prompt_host(1_ms);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(5000), us(300));
  b.latch_pulse(us(7000), us(300));
  b.start_pulse(us(10000), us(300)); // S2: TM2 = 3,000
  b.start_pulse(us(14999), us(1));   // held off
  b.start_pulse(us(15000), us(300)); // S1
  b.latch_pulse(us(17000), us(300)); // L1: TM1 = 2,000
  b.latch_pulse(us(20000), us(300)); // L2
  b.start_pulse(us(21000), us(300)); // S2: TM2 = 1,000
  b.run_until(25_ms);
  EXPECT_EQ(b.word(1), 2);
  EXPECT_EQ(b.word(2), 0);
  EXPECT_EQ(b.word(3), 1);
  EXPECT_EQ(b.word(4), 0);
}

// W15: with T3 = 8 ms the hold is 8 ms. S2 at 20,000 us (TM2 = 8,000): Start at 27,999
// ignored, 28,000 accepted; L1 at 28,500 -> TM1 = 500 us.
TEST(Amci4501Mode4, FilterTwoHoldsTmTwoWhenLonger) {
  Bench b;
  b.program_mode(4);
  b.prompt_host(1_ms);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(5000), us(300));
  b.latch_pulse(us(12000), us(300)); // L2, 7,000 after L1 >= 1,000
  b.start_pulse(us(20000), us(300)); // S2: TM2 = 8,000
  b.start_pulse(us(27999), us(1));
  b.start_pulse(us(28000), us(300));
  b.latch_pulse(us(28500), us(100)); // L1: TM1 = 500
  b.latch_pulse(us(30000), us(100)); // L2
  b.start_pulse(us(31000), us(100)); // S2: TM2 = 1,000
  b.run_until(35_ms);
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 500);
  EXPECT_EQ(b.word(3), 1);
  EXPECT_EQ(b.word(4), 0);
}

// W11 (L97): fw v3, timeout with only S1 seen: bit 6 and words 1-4 = 0. Timeout 100 ms,
// S1 at 1 ms -> at 101 ms.
TEST(Amci4501Mode4, TimeoutAfterOnlyFirstStart) {
  Bench b;
  b.program_mode(4, 100);
  b.start_pulse(1_ms, us(300));
  b.run_until(101_ms);
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 0);
  EXPECT_EQ(b.word(2), 0);
  EXPECT_EQ(b.word(3), 0);
  EXPECT_EQ(b.word(4), 0);
}

// W12 (L98): S1 at 1 ms, L1 at 13.345 ms: TM1 = 12,345 us reported, TM2 = 0.
TEST(Amci4501Mode4, TimeoutAfterFirstLatchReportsTmOne) {
  Bench b;
  b.program_mode(4, 100);
  b.start_pulse(1_ms, us(300));
  b.latch_pulse(us(13345), us(300));
  b.run_until(101_ms - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 0);
  b.run_until(101_ms);
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 12);
  EXPECT_EQ(b.word(2), 345);
  EXPECT_EQ(b.word(3), 0);
  EXPECT_EQ(b.word(4), 0);
}

// W13 (L102): S1, L1, L2 seen, S2 missing: TM1 reported, TM2 = 0.
TEST(Amci4501Mode4, TimeoutWithoutSecondStartReportsTmOne) {
  Bench b;
  b.program_mode(4, 100);
  b.start_pulse(1_ms, us(300));
  b.latch_pulse(5_ms, us(300));
  b.latch_pulse(8_ms, us(300));
  b.run_until(101_ms);
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 4);
  EXPECT_EQ(b.word(2), 0);
  EXPECT_EQ(b.word(3), 0);
  EXPECT_EQ(b.word(4), 0);
}

// L36, L95 (A19): before firmware 3 a timeout reports nothing; before firmware 2 the
// filters are absent (the W14 case then takes the 5,999 us Latch: TM2 = 3,001).
TEST(Amci4501Mode4, FirmwareVersionGatesFeatures) {
  Params p;
  p.fw_version = 1;
  Bench b{p};
  b.program_mode(4, 100);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(5000), us(300));
  b.latch_pulse(us(5999), us(1));
  b.start_pulse(us(9000), us(300));
  b.run_until(12_ms);
  EXPECT_EQ(b.word(3), 3);
  EXPECT_EQ(b.word(4), 1);
  b.module->write_output(0, control::kReceived);
  b.start_pulse(20_ms, us(300));
  b.latch_pulse(25_ms, us(300));
  b.run_until(121_ms);
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_EQ(b.word(1), 4) << "fw < 3: the words keep the last result";
}

} // namespace
} // namespace hilrig::models::amci4501::test
