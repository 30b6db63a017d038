// The programming cycle (digest §5.3-5.4): Transmit/Acknowledge, Command and Parameter
// errors, ranges, don't-care words, and the status mode bits.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// W22 (L168, L295-310): Transmit 0->1 latches the words and sets Acknowledge; Transmit
// 1->0 drops it.
TEST(Amci4501Programming, TransmitAcknowledgeHandshake) {
  Bench b;
  std::array<std::uint16_t, 8> w{static_cast<std::uint16_t>(control::kMode3 | control::kTransmit), 500};
  b.module->write_output_words(0, w);
  EXPECT_TRUE(b.bit(status::kAcknowledge));
  EXPECT_EQ(b.module->mode(), 3);
  EXPECT_EQ(b.module->config().timeout_word, 500);
  // Mode 4 during a programming ack = 0x8400 (digest §5.2 [D]).
  b.module->write_output(0, control::kMode4);
  b.module->write_output(0, control::kMode4 | control::kTransmit);
  EXPECT_EQ(b.status(), 0x8400);
  EXPECT_EQ(static_cast<std::int16_t>(b.status()), -31744);
  b.module->write_output(0, control::kMode4);
  EXPECT_EQ(b.status(), 0x0400);
}

// W23 (L87-110): bits 8-12 = modes 2-6; mode 1 has none (A31).
TEST(Amci4501Programming, ModeStatusBits) {
  Bench b;
  EXPECT_EQ(b.status(), 0);
  for (int mode = 2; mode <= 6; ++mode) {
    if (mode == 2)
      b.program_window(1, 2); // mode 2 needs on < off (L171)
    else
      b.program_mode(mode);
    EXPECT_EQ(b.module->mode(), mode);
    EXPECT_EQ(b.status(), 1u << (mode + 6)) << "mode " << mode;
  }
  b.program(0, {1000});
  EXPECT_EQ(b.module->mode(), 1);
  EXPECT_EQ(b.status(), 0);
}

// L92, L118 (A30): two mode bits or a reserved bit -> Command Error, previous configuration
// kept, acknowledge still given (MODEL); the next valid cycle clears it.
TEST(Amci4501Programming, CommandErrors) {
  Bench b;
  b.program_mode(3);
  b.program(control::kMode3 | control::kMode5);
  EXPECT_TRUE(b.ack_seen);
  EXPECT_TRUE(b.bit(status::kCommandError));
  EXPECT_EQ(b.module->mode(), 3);
  b.program(control::kMode4 | (1u << 9), {1000});
  EXPECT_TRUE(b.bit(status::kCommandError));
  EXPECT_EQ(b.module->mode(), 3);
  b.program_mode(4);
  EXPECT_FALSE(b.bit(status::kCommandError));
  EXPECT_EQ(b.module->mode(), 4);
}

// W4 (L170): setpoint 34,567 is written 34 / 567. W6, W7: timeout 0..32,767 and
// setpoints 0..65,535 are valid; on < off (L171).
TEST(Amci4501Programming, WindowSetpointsAndRanges) {
  Bench b;
  b.program(control::kMode2, {1000, 34, 567, 40, 0});
  EXPECT_FALSE(b.bit(status::kParameterError));
  EXPECT_EQ(b.module->config().on_setpoint, 34567u);
  EXPECT_EQ(b.module->config().off_setpoint, 40000u);
  b.program(control::kMode2, {32767, 0, 0, 65, 535}); // extremes: on = 0 (A16), off = 65,535
  EXPECT_FALSE(b.bit(status::kParameterError));
  EXPECT_EQ(b.module->config().off_setpoint, 65535u);
  EXPECT_EQ(b.module->config().timeout_word, 32767);

  const Config kept = b.module->config();
  const std::array<std::array<std::uint16_t, 7>, 5> bad{{
      {32768, 0, 1, 1, 0},   // timeout above 32,767
      {1000, 0, 1, 65, 536}, // off setpoint 65,536
      {1000, 2, 0, 2, 0},    // on == off
      {1000, 3, 0, 2, 0},    // on > off
      {1000, 0, 1000, 5, 0}, // lower word above 999 (MODEL)
  }};
  for (const auto& words : bad) {
    b.program(control::kMode2, words);
    EXPECT_TRUE(b.bit(status::kParameterError)) << words[0] << " " << words[2] << "/" << words[3];
    EXPECT_EQ(b.module->config(), kept);
  }
  b.program_mode(1);
  EXPECT_FALSE(b.bit(status::kParameterError));
}

// L177, A29: don't-care words are not checked (setpoints in mode 3, timeout in mode 5).
TEST(Amci4501Programming, DontCareWordsAreIgnored) {
  Bench b;
  b.program(control::kMode3, {1000, 9999, 9999, 0, 0, 7, 7});
  EXPECT_FALSE(b.bit(status::kParameterError));
  b.program(control::kMode5, {40000});
  EXPECT_FALSE(b.bit(status::kParameterError));
  EXPECT_EQ(b.module->mode(), 5);
}

// The pure validator agrees with the split rule: value = 1000·upper + lower (L170).
TEST(Amci4501Programming, SplitRoundTrip) {
  for (std::uint64_t v : {0ull, 1ull, 999ull, 1000ull, 12345ull, 34567ull, 65535ull}) {
    const SplitWords s = split_thousands(v);
    EXPECT_EQ(join_thousands(s.upper, s.lower), v);
    EXPECT_LE(s.lower, 999);
  }
  EXPECT_EQ(split_thousands(12345), (SplitWords{12, 345}));
  EXPECT_EQ(split_thousands(34567), (SplitWords{34, 567}));
}

// [MODEL] A valid programming cycle drops an unacknowledged result and starts afresh.
TEST(Amci4501Programming, ReprogrammingClearsResults) {
  Bench b;
  b.start_pulse(1_ms, us(100));
  b.latch_pulse(2_ms, us(100));
  b.run_until(3_ms);
  EXPECT_TRUE(b.bit(status::kNewValue));
  b.program_mode(3);
  EXPECT_FALSE(b.bit(status::kNewValue));
  EXPECT_EQ(b.words(), (InputWords{mode_status_bit(3), 0, 0, 0, 0, 0, 0, 0}));
}

} // namespace
} // namespace hilrig::models::amci4501::test

namespace hilrig::models::amci4501::test {
namespace {

// A10 parameter: with level acknowledge, a host that holds O:0/0 high and writes it with
// every scan acknowledges each result; with the default edge acknowledge the second
// result waits for a fresh 0->1.
TEST(Amci4501Programming, AcknowledgeLevelOrEdge) {
  for (const bool edge : {true, false}) {
    Params p;
    p.acknowledge_on_rising_edge = edge;
    Bench b{p};
    b.write_at(1_ms, control::kReceived); // held high from here on
    for (int k = 1; k <= 2; ++k) {
      b.start_pulse(milliseconds(10 * k), us(200));
      b.latch_pulse(milliseconds(10 * k + 5), us(200));
    }
    b.write_at(17_ms, control::kReceived); // the host's scan rewrites the same word
    b.run_until(20_ms);
    EXPECT_EQ(b.bit(status::kNewValue), edge) << (edge ? "edge" : "level");
    b.run_until(30_ms);
    EXPECT_EQ(b.module->results_published(), edge ? 1u : 2u);
  }
}

// A30 parameter: an invalid programming cycle may go unacknowledged.
TEST(Amci4501Programming, InvalidProgramAcknowledgeIsAParameter) {
  Params p;
  p.acknowledge_invalid_program = false;
  Bench b{p};
  b.program(control::kMode3 | control::kMode4);
  EXPECT_FALSE(b.ack_seen);
  EXPECT_TRUE(b.bit(status::kCommandError));
  b.program_mode(3);
  EXPECT_TRUE(b.ack_seen);
}

} // namespace
} // namespace hilrig::models::amci4501::test
