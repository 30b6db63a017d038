// Control bits 0 and 1 and the programming cycle (digest §5.4). The manual:
// "Output bits 0 and 1 are not part of a programming cycle. These bits will be acted on
// immediately after being set" (seeds/001_8422c5eec3a3e376.txt:167); only bits 2-6 and words
// 1-5 need a programming cycle (L168). Bit 0 tells the module the measurement was received,
// the module freezes the values until it is set (L153); bit 1 clears No Response and Time Out
// (L154). Nothing in the manual makes a programming cycle clear a result or end a cycle, so
// a host whose ladder copies its whole output image with Transmit (the example, L295-310) and
// acknowledges that way keeps its last measurement and its running mode 1 cycle. The old
// behaviour is the [MODEL] option program_clears_results (README).
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// W1 (L7): Start at 1 ms, one turn = 4,096 X4 counts from 2 ms, 10 us apart (ends 42.95 ms),
// Latch at 43.5 ms; the result is out one throughput (125 us, L281) later.
void one_turn(Bench& b) {
  b.start_pulse(us(1000), us(500));
  b.burst(4096, us(2000), us(10));
  b.latch_pulse(us(43500), us(500));
}

TEST(Amci4501ControlBits, AcknowledgeInAProgrammingCycleKeepsTheLastMeasurement) {
  // Acknowledge by a programming cycle carrying bit 0 (same mode 1), at several times after
  // the result: New Measurement drops (bit 0 acted on), the result words stay (L153).
  for (Nanos at : {us(43625), us(43626), 50_ms, 400_ms}) {
    Bench b;
    one_turn(b);
    b.run_until(at);
    ASSERT_TRUE(b.bit(status::kNewValue)) << at.count();
    b.program(control::kReceived, {1000});
    EXPECT_TRUE(b.ack_seen);
    EXPECT_FALSE(b.bit(status::kNewValue)) << at.count();
    EXPECT_EQ(b.word(1), 4096) << at.count();
    b.run_until(at + 10_ms);
    EXPECT_EQ(b.word(1), 4096) << at.count();
  }
}

TEST(Amci4501ControlBits, ProgrammingCycleDuringAMode1CycleDoesNotAbortIt) {
  // A same-mode programming cycle (with and without bit 0) anywhere inside the Start..Latch
  // cycle: the cycle runs on, the Cycle Output stays on, and the Latch gives the full turn.
  for (Nanos at : {us(1126), us(1999), us(2001), 20_ms, us(42950), us(43499)}) {
    for (std::uint16_t bit0 : {std::uint16_t{0}, control::kReceived}) {
      Bench b;
      one_turn(b);
      b.scheduler.at(at, [&b, bit0] { b.program(bit0, {1000}); });
      b.run_until(50_ms);
      EXPECT_TRUE(b.bit(status::kNewValue)) << at.count();
      EXPECT_EQ(b.word(1), 4096) << at.count() << " bit0 " << bit0;
      ASSERT_EQ(b.cycle_edges.size(), 2u) << at.count();
      EXPECT_EQ(b.cycle_edges[1].time, us(43625)); // off at Latch + throughput (L212, L281)
    }
  }
}

TEST(Amci4501ControlBits, BitsZeroAndOneActAtOnceWithoutTransmit) {
  // L167: a raw control word write, no Transmit: bit 0 drops New Measurement at once, bit 1
  // clears Time Out at once (L154). The mode 1 timeout (word 1 = 1,000 ms, L169) expires with
  // no Latch.
  Bench b;
  one_turn(b);
  b.run_until(44_ms);
  ASSERT_TRUE(b.bit(status::kNewValue));
  b.module->write_output(0, control::kReceived);
  EXPECT_FALSE(b.bit(status::kNewValue));
  EXPECT_FALSE(b.bit(status::kAcknowledge)); // no programming cycle happened
  EXPECT_EQ(b.word(1), 4096);
  b.module->write_output(0, 0);
  b.start_pulse(50_ms, us(500));
  b.run_until(50_ms + 10_s + 1_ms); // default timeout 10 s (word 1 = 0, L169)
  ASSERT_TRUE(b.bit(status::kTimeout));
  b.module->write_output(0, control::kClearError);
  EXPECT_FALSE(b.bit(status::kTimeout));
  EXPECT_FALSE(b.bit(status::kAcknowledge));
}

TEST(Amci4501ControlBits, ProgramClearsResultsOptionRestoresTheOldBehaviour) {
  // The [MODEL] option: a valid programming cycle clears the results and aborts the cycle.
  Params p;
  p.program_clears_results = true;
  Bench b(p);
  one_turn(b);
  b.run_until(44_ms);
  b.program(control::kReceived, {1000});
  EXPECT_EQ(b.word(1), 0);
  Bench running(p);
  one_turn(running);
  running.scheduler.at(20_ms, [&running] { running.program(0, {1000}); });
  running.run_until(50_ms);
  EXPECT_FALSE(running.bit(status::kNewValue));
}

TEST(Amci4501ControlBits, AModeChangeStillStartsAfresh) {
  // [MODEL] (README): a programming cycle that changes the mode drops the old mode's cycle:
  // the Cycle Output goes off at once.
  Bench b;
  one_turn(b);
  b.scheduler.at(20_ms, [&b] { b.program(control::kMode3, {1000}); });
  b.run_until(30_ms);
  ASSERT_EQ(b.cycle_edges.size(), 2u);
  EXPECT_EQ(b.cycle_edges[1].time, 20_ms);
  EXPECT_FALSE(b.cycle_edges[1].on);
}

TEST(Amci4501ControlBits, AModeChangeDropsAnOutputChangeStillOnItsWay) {
  // A mode change ends the cycle (mode 1) or the window (mode 2) at once: an output change
  // still on its way (one throughput, 125 us, after its edge, L281) never lands (L7, L12).
  // Mode 1: Start at 1 ms, ON due at 1,125 us; the mode changes at 1,124 / 1,125 / 1,126 us.
  for (const auto& [at, edges] :
       {std::pair{us(1124), 0u}, std::pair{us(1125), 0u}, std::pair{us(1126), 2u}}) {
    Bench b;
    one_turn(b);
    b.scheduler.at(at, [&b] { b.program(control::kMode3, {1000}); });
    b.run_until(50_ms);
    EXPECT_EQ(b.cycle_edges.size(), edges) << at.count();
    EXPECT_FALSE(b.module->cycle_output_on()) << at.count();
  }
  // Mode 2: window 100..300 opens at 1,990 us, Latch on at 3 ms (ON due at 3,125 us); the
  // mode changes to 1 at 3,100 us.
  Bench b;
  b.program_window(100, 300);
  b.burst(150, us(1000), us(10));
  b.latch_pulse(3_ms, 1_ms);
  b.scheduler.at(us(3100), [&b] { b.program(0, {1000}); });
  b.run_until(10_ms);
  EXPECT_TRUE(b.cycle_edges.empty());
  EXPECT_FALSE(b.module->cycle_output_on());
}

} // namespace
} // namespace hilrig::models::amci4501::test
