// Mode 1, registration from Start to Latch (digest §3.1), the result handshake and No
// Response (§5.4), timeouts (§3.0) and the velocity word.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// W1 (L7): one turn of a 1,024-line encoder is 4,096 X4 counts. Start at 1,000 us, the
// turn F(4096, 2000, 10) ends at 2000 + 4095·10 = 42,950 us, Latch at 43,500 us: both
// edges 200 us clear of the encoder (examples §0.4).
TEST(Amci4501Mode1, OneTurnIsFourThousandNinetySixCounts) {
  Bench b;
  b.start_pulse(us(1000), us(500));
  b.burst(4096, us(2000), us(10));
  b.latch_pulse(us(43500), us(500));
  b.run_until(us(43500) + us(124));
  EXPECT_FALSE(b.bit(status::kNewValue)) << "published before the 125 us throughput";
  b.run_until(us(43500) + us(125));
  EXPECT_TRUE(b.bit(status::kNewValue));
  EXPECT_EQ(b.word(1), 4096);
  EXPECT_EQ(b.module->position(), 4096);
}

// L7, L212: the Cycle Output is on from the Start edge to the Latch edge, each edge one
// throughput (125 us, L281) after its trigger.
TEST(Amci4501Mode1, CycleOutputSpansStartToLatch) {
  Bench b;
  b.start_pulse(us(1000), us(500));
  b.burst(100, us(2000), us(10));
  b.latch_pulse(us(5000), us(500));
  b.run_until(10_ms);
  ASSERT_EQ(b.cycle_edges.size(), 2u);
  EXPECT_EQ(b.cycle_edges[0].time, us(1125));
  EXPECT_TRUE(b.cycle_edges[0].on);
  EXPECT_EQ(b.cycle_edges[1].time, us(5125));
  EXPECT_FALSE(b.cycle_edges[1].on);
  EXPECT_EQ(b.word(1), 100);
}

// W2 (L7): the registration value reaches 65,535 counts; as a signed SLC INT it reads -1
// (digest §3.1 [D]). F(65535, 2000, 4) ends at 2000 + 65534·4 = 264,136 us (62.5 kHz per
// channel, inside 250 kHz under either reading, A3).
TEST(Amci4501Mode1, MaximumRegistrationValue) {
  Bench b;
  b.start_pulse(us(1000), us(500));
  b.burst(65535, us(2000), us(4));
  b.latch_pulse(us(265000), us(500));
  b.run_until(270_ms);
  EXPECT_EQ(b.word(1), 65535);
  EXPECT_EQ(static_cast<std::int16_t>(b.word(1)), -1);
  EXPECT_EQ(b.module->count_overflows(), 0u);
}

// A11 [I]: the counter is up/down, the value is the net signed count: +100 then -30 = 70.
TEST(Amci4501Mode1, ReversalGivesNetCount) {
  Bench b;
  b.start_pulse(us(1000), us(500));
  b.burst(100, us(2000), us(10));
  b.burst(-30, us(4000), us(10));
  b.latch_pulse(us(6000), us(500));
  b.run_until(10_ms);
  EXPECT_EQ(b.word(1), 70);
}

// A11 [I]: Latch with no cycle is ignored; a second Start inside a cycle does not restart it.
TEST(Amci4501Mode1, LatchWithoutStartAndRetriggerAreIgnored) {
  Bench b;
  b.latch_pulse(us(500), us(200)); // no cycle yet
  b.start_pulse(us(1000), us(200));
  b.burst(50, us(2000), us(10));
  b.start_pulse(us(3000), us(200)); // re-trigger: ignored
  b.burst(25, us(4000), us(10));
  b.latch_pulse(us(5000), us(200));
  b.run_until(10_ms);
  EXPECT_EQ(b.module->results_published(), 1u);
  EXPECT_EQ(b.word(1), 75);
}

// W18 (L114): velocity = counts per 50 ms, refreshed every 50 ms, negative when B leads A.
// R(12000, 40,005 us, 10 us) runs 40.005-160.0 ms at 100,000 counts/s; the window
// (100, 150] ms holds 5,000 edges, so the word refreshed at 150 ms is -5,000.
TEST(Amci4501Mode1, VelocityIsSignedCountsPer50ms) {
  Bench b;
  b.burst(-12000, us(40005), us(10));
  b.run_until(150_ms);
  EXPECT_EQ(static_cast<std::int16_t>(b.word(2)), -5000);
  b.run_until(200_ms);
  // Edges at 40,005 + 10k us, k = 0..11,999: the last at 159,995 us. In (150, 200] ms:
  // k = 11,000 .. 11,999 -> 1,000 edges.
  EXPECT_EQ(static_cast<std::int16_t>(b.word(2)), -1000);
  b.run_until(250_ms);
  EXPECT_EQ(b.word(2), 0);
}

// W10 (L88): a host that never acknowledges. Cycle 1 is reported; cycles 2-5 are missed;
// No Response comes on at the end of the 4th missed cycle (the 5th cycle), not before.
// Cycle k: Start at k·10 ms, k edges, Latch at k·10 ms + 5 ms.
TEST(Amci4501Mode1, NoResponseAfterFourMissedCycles) {
  Bench b;
  for (int k = 1; k <= 6; ++k) {
    const Nanos t = milliseconds(10 * k);
    b.start_pulse(t, us(200));
    b.burst(k, t + us(1000), us(10));
    b.latch_pulse(t + 5_ms, us(200));
  }
  b.run_until(milliseconds(45) + us(125)); // 4th cycle's Latch + throughput
  EXPECT_FALSE(b.bit(status::kNoResponse)) << "after 3 missed cycles";
  b.run_until(milliseconds(55) + us(125)); // 5th cycle's Latch + throughput
  EXPECT_TRUE(b.bit(status::kNoResponse));
  EXPECT_EQ(b.word(1), 1) << "words stay frozen at the reported cycle";
  EXPECT_EQ(b.module->results_missed(), 4u);
  // Control bit 0 acknowledges (bit 0 drops), bit 1 clears No Response (L154).
  b.module->write_output(0, control::kReceived);
  EXPECT_FALSE(b.bit(status::kNewValue));
  EXPECT_TRUE(b.bit(status::kNoResponse)) << "acknowledge does not clear No Response";
  b.module->write_output(0, control::kClearError);
  EXPECT_FALSE(b.bit(status::kNoResponse));
  b.run_until(80_ms); // the 6th cycle is published
  EXPECT_EQ(b.word(1), 6);
  EXPECT_TRUE(b.bit(status::kNewValue));
}

// A4: the threshold is a parameter; with 5 (L223's reading) the 5th cycle does not set it.
TEST(Amci4501Mode1, NoResponseThresholdIsAParameter) {
  Params p;
  p.no_response_missed = 5;
  Bench b{p};
  for (int k = 1; k <= 6; ++k) {
    const Nanos t = milliseconds(10 * k);
    b.start_pulse(t, us(200));
    b.latch_pulse(t + 5_ms, us(200));
  }
  b.run_until(milliseconds(56));
  EXPECT_FALSE(b.bit(status::kNoResponse));
  b.run_until(milliseconds(66));
  EXPECT_TRUE(b.bit(status::kNoResponse));
}

// Host policy H (examples §0.2) sees every cycle: each is published with its own value.
TEST(Amci4501Mode1, PromptHostReceivesEveryCycle) {
  Bench b;
  b.prompt_host(1_ms);
  for (int k = 1; k <= 5; ++k) {
    const Nanos t = milliseconds(10 * k);
    b.start_pulse(t, us(200));
    b.burst(10 * k, t + us(1000), us(10));
    b.latch_pulse(t + 5_ms, us(200));
    b.run_until(t + 9_ms);
    EXPECT_EQ(b.word(1), 10 * k) << "cycle " << k;
  }
  EXPECT_EQ(b.module->results_published(), 5u);
  EXPECT_EQ(b.module->results_missed(), 0u);
  EXPECT_FALSE(b.bit(status::kNoResponse));
}

// L93, L119, L154: timeout 1,000 ms (examples §0.2). Start at 1 ms and no Latch: Time Out
// at exactly 1,001 ms, the Cycle Output off, later Start/Latch do nothing until control bit
// 1 clears it; then a cycle runs again.
TEST(Amci4501Mode1, TimeoutBlocksUntilCleared) {
  Bench b;
  b.program_mode(1, 1000);
  b.start_pulse(1_ms, us(200));
  b.run_until(milliseconds(1001) - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  EXPECT_TRUE(b.module->cycle_output_on());
  b.run_until(milliseconds(1001));
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_FALSE(b.module->cycle_output_on());
  b.start_pulse(milliseconds(1100), us(200));
  b.latch_pulse(milliseconds(1105), us(200));
  b.run_until(milliseconds(1200));
  EXPECT_FALSE(b.bit(status::kNewValue)) << "no cycle while Time Out is set";
  b.module->write_output(0, control::kClearError);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.start_pulse(milliseconds(1300), us(200));
  b.burst(7, milliseconds(1301), us(10));
  b.latch_pulse(milliseconds(1305), us(200));
  b.run_until(milliseconds(1310));
  EXPECT_TRUE(b.bit(status::kNewValue));
  EXPECT_EQ(b.word(1), 7);
}

// L7: the Cycle Output is active "while the encoder pulses are being counted"; a Time Out
// abandons the cycle (L93), so the output is off from then on, even when its turn-on (one
// throughput after Start, L281) has not landed yet. A throughput of at least the timeout is
// beyond the manual's 125 us but a campaign may set it (the knob `hilrig power` turns). Start
// at 1 ms, timeout 1 ms: Time Out at 2 ms.
TEST(Amci4501Mode1, TimeoutDropsATurnOnStillOnItsWay) {
  for (const auto& [throughput, pulse] :
       {std::pair{us(999), true}, std::pair{us(1000), false}, std::pair{us(1001), false}}) {
    Params p;
    p.throughput = throughput;
    Bench b(p);
    b.program_mode(1, 1);
    b.start_pulse(1_ms, us(200));
    b.run_until(10_ms);
    EXPECT_TRUE(b.bit(status::kTimeout)) << throughput.count();
    EXPECT_FALSE(b.module->cycle_output_on()) << throughput.count();
    if (pulse) {
      ASSERT_EQ(b.cycle_edges.size(), 2u);
      EXPECT_EQ(b.cycle_edges[0].time, 1_ms + throughput);
      EXPECT_EQ(b.cycle_edges[1].time, 2_ms);
      EXPECT_FALSE(b.cycle_edges[1].on);
    } else {
      EXPECT_TRUE(b.cycle_edges.empty()) << throughput.count(); // lands at or after Time Out
    }
  }
}

// L119: "The module will not update the input image table data until the timeout error has
// been cleared" - the velocity word too (L114). Timeout 60 ms, Start at 1 ms and no Latch:
// Time Out at 61 ms. F(15000, 40,005 us, 10 us) runs 40.005-190.0 ms at 100,000 counts/s.
// The window ending at 50 ms (before Time Out) holds 1,000 edges and is written; the ones
// ending at 100 and 150 ms (5,000 edges each) are not. Control bit 1 at 160 ms (L154): the
// window ending at 200 ms holds k = 11,000 .. 14,999, 4,000 edges, and is written again.
TEST(Amci4501Mode1, TimeoutFreezesTheVelocityWordUntilCleared) {
  Bench b;
  b.program_mode(1, 60);
  b.start_pulse(1_ms, us(200));
  b.burst(15000, us(40005), us(10));
  b.run_until(50_ms);
  EXPECT_EQ(b.word(2), 1000);
  b.run_until(61_ms - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.run_until(61_ms);
  EXPECT_TRUE(b.bit(status::kTimeout));
  for (Nanos t : {100_ms - 1_ns, 100_ms, 150_ms, 160_ms - 1_ns}) {
    b.run_until(t);
    EXPECT_EQ(b.word(2), 1000) << t.count();
  }
  b.module->write_output(0, control::kClearError);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.run_until(200_ms - 1_ns);
  EXPECT_EQ(b.word(2), 1000) << "written at the window's end only";
  b.run_until(200_ms);
  EXPECT_EQ(b.word(2), 4000);
}

// W5 (L169): timeout word 0 means 10 s. Power-up state is mode 1 with timeout 0 (§5.4).
TEST(Amci4501Mode1, TimeoutZeroMeansTenSeconds) {
  Bench b;
  EXPECT_EQ(b.module->mode(), 1);
  EXPECT_EQ(b.module->config().timeout_word, 0);
  b.start_pulse(1_ms, us(200));
  b.run_until(milliseconds(10001) - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.run_until(milliseconds(10001));
  EXPECT_TRUE(b.bit(status::kTimeout));
}

// Property: for random bursts forward and back between Start and Latch, the registration
// value is the net edge count (sum of the signed burst sizes) modulo 2^16 (A11).
TEST(Amci4501Mode1, PropertyNetCountOfRandomBursts) {
  std::mt19937 rng(4501);
  for (int run = 0; run < 20; ++run) {
    Bench b;
    b.prompt_host(1_ms);
    std::int64_t net = 0;
    Nanos t = 2_ms;
    std::uniform_int_distribution<int> size(-300, 600);
    for (int i = 0; i < 6; ++i) {
      const int n = size(rng);
      if (n == 0) continue;
      b.burst(n, t, us(10));
      net += n;
      t += us(10) * (n < 0 ? -n : n) + us(500);
    }
    b.start_pulse(1_ms, us(200));
    b.latch_pulse(t, us(200));
    b.run_until(t + 5_ms);
    EXPECT_EQ(b.word(1), static_cast<std::uint16_t>(net)) << "run " << run;
  }
}

} // namespace
} // namespace hilrig::models::amci4501::test
