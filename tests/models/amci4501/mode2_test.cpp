// Mode 2, registration in an enable window (digest §3.2): L1-L4 from the first two Latch
// pulses inside Son <= P < Soff, the Cycle Output copying them, Z, velocity.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

// Son = 1,000, Soff = 3,000. The encoder moves in bursts at 10 us/edge with rests, and
// every Latch edge falls in a rest (examples §0.4), so P at each edge is a sum of bursts:
//   F(1200, 1000, 10): P = 1200 by 12,990 us; the window opens at edge 1,000 (10,990 us)
//   Latch on 13,500 -> L1 = 1200 - 1000 = 200
//   F(100, 14000, 10): P = 1300;   Latch off 15,500 -> L2 = 300
//   F(200, 16000, 10): P = 1500;   Latch on 18,500  -> L3 = 500
//   F(100, 19000, 10): P = 1600;   Latch off 20,500 -> L4 = 600
//   third pulse 21,000-21,300: ignored (L12, L115)
//   F(1500, 22000, 10): P reaches 3,000 at edge 1,400: 22,000 + 1,399·10 = 35,990 us
//   -> window closes, words 1-4 published 125 us later (36,115 us).
TEST(Amci4501Mode2, TwoPulsesInTheWindow) {
  Bench b;
  b.program_window(1000, 3000);
  b.burst(1200, us(1000), us(10));
  b.latch_at(us(13500), Level::High);
  b.burst(100, us(14000), us(10));
  b.latch_at(us(15500), Level::Low);
  b.burst(200, us(16000), us(10));
  b.latch_at(us(18500), Level::High);
  b.burst(100, us(19000), us(10));
  b.latch_at(us(20500), Level::Low);
  b.latch_pulse(us(21000), us(300));
  b.burst(1500, us(22000), us(10));
  b.run_until(us(10990) - 1_ns);
  EXPECT_FALSE(b.module->window_open());
  b.run_until(us(10990));
  EXPECT_TRUE(b.module->window_open());
  b.run_until(us(36115) - 1_ns);
  EXPECT_FALSE(b.bit(status::kNewValue));
  b.run_until(us(36115));
  EXPECT_FALSE(b.module->window_open());
  EXPECT_TRUE(b.bit(status::kNewValue));
  EXPECT_EQ(b.word(1), 200);
  EXPECT_EQ(b.word(2), 300);
  EXPECT_EQ(b.word(3), 500);
  EXPECT_EQ(b.word(4), 600);
  EXPECT_TRUE(b.bit(status::kMode2));
  // L12: the output copies the first two pulses, each edge one throughput late (L281).
  ASSERT_EQ(b.cycle_edges.size(), 4u);
  EXPECT_EQ(b.cycle_edges[0].time, us(13625));
  EXPECT_TRUE(b.cycle_edges[0].on);
  EXPECT_EQ(b.cycle_edges[1].time, us(15625));
  EXPECT_EQ(b.cycle_edges[2].time, us(18625));
  EXPECT_EQ(b.cycle_edges[3].time, us(20625));
  EXPECT_FALSE(b.cycle_edges[3].on);
}

// W9 (L226): one pulse in the window -> words 3 and 4 are 0. A pulse before the window
// opens is not counted either.
TEST(Amci4501Mode2, OnePulseLeavesWordsThreeAndFourZero) {
  Bench b;
  b.program_window(100, 500);
  b.latch_pulse(us(500), us(200));   // P = 0: outside the window
  b.burst(150, us(1000), us(10));    // P = 150 by 2,490 us (window open at edge 100)
  b.latch_at(us(3000), Level::High); // L1 = 50
  b.burst(100, us(3500), us(10));    // P = 250
  b.latch_at(us(5000), Level::Low);  // L2 = 150
  b.burst(300, us(5500), us(10));    // P reaches 500 at 5,500 + 249·10 = 7,990 us
  b.run_until(10_ms);
  EXPECT_EQ(b.word(1), 50);
  EXPECT_EQ(b.word(2), 150);
  EXPECT_EQ(b.word(3), 0);
  EXPECT_EQ(b.word(4), 0);
  EXPECT_EQ(b.cycle_edges.size(), 2u);
}

// L12, L330: the Cycle Output is forced off when the window ends, even with Latch still
// active; the trailing edge never came, so L2 = 0 ([I] A14).
TEST(Amci4501Mode2, WindowEndForcesTheOutputOff) {
  Bench b;
  b.program_window(100, 300);
  b.burst(150, us(1000), us(10));    // window opens at edge 100 = 1,990 us
  b.latch_at(us(3000), Level::High); // L1 = 50
  b.burst(200, us(3500), us(10));    // P = 300 at edge 150: 3,500 + 149·10 = 4,990 us
  b.latch_at(us(6000), Level::Low);  // after the window
  b.run_until(10_ms);
  ASSERT_EQ(b.cycle_edges.size(), 2u);
  EXPECT_EQ(b.cycle_edges[0].time, us(3125));
  EXPECT_EQ(b.cycle_edges[1].time, us(4990) + us(125));
  EXPECT_FALSE(b.cycle_edges[1].on);
  EXPECT_EQ(b.word(1), 50);
  EXPECT_EQ(b.word(2), 0);
}

// A14 [I]: a Latch already active when the window opens has no leading edge inside it.
TEST(Amci4501Mode2, LatchActiveAtWindowOpenIsNotCounted) {
  Bench b;
  b.program_window(100, 300);
  b.latch_at(us(500), Level::High);
  b.burst(150, us(1000), us(10));
  b.latch_at(us(3000), Level::Low);  // trailing edge of an uncounted pulse
  b.latch_at(us(3200), Level::High); // this is the first pulse: L1 = 50
  b.latch_at(us(3400), Level::Low);  // L2 = 50
  b.burst(200, us(3500), us(10));
  b.run_until(10_ms);
  EXPECT_EQ(b.word(1), 50);
  EXPECT_EQ(b.word(2), 50);
  EXPECT_EQ(b.word(3), 0);
}

// W16, L12: a Z pulse zeroes the position; the window then opens on the count from 0.
// Son = 600: F(500) -> P = 500 (window still shut); Z at 7,000 us -> P = 0; F(650) -> the
// window opens at the 600th edge after Z: 8,000 + 599·10 = 13,990 us, not at the 100th
// (where P would have reached 600 without the Z reset: 8,990 us).
TEST(Amci4501Mode2, IndexPulseZeroesThePosition) {
  Bench b;
  b.program_window(600, 4000);
  b.burst(500, us(1000), us(10));
  b.z_pulse(us(7000), us(10));
  b.burst(650, us(8000), us(10));
  b.run_until(us(7500));
  EXPECT_EQ(b.module->position(), 0);
  b.run_until(us(13990) - 1_ns);
  EXPECT_FALSE(b.module->window_open());
  b.run_until(us(13990));
  EXPECT_TRUE(b.module->window_open());
  EXPECT_EQ(b.module->position(), 600);
}

// W17 (L174, L331): program the on setpoint >= 1, so that the window opens on a count after
// the Z reset rather than racing it. Son = 1 is accepted. F(300) runs one window
// (P = 1 .. 200) and leaves P = 300; Z at 5,000 us -> P = 0 with the window shut; the next
// window opens at the first edge after Z (P = 1: 6,000 us) and closes at Soff = 200, the
// 200th edge (6,000 + 199 * 10 = 7,990 us).
TEST(Amci4501Mode2, W17OnSetpointOneOpensTheWindowOnTheFirstCountAfterZ) {
  Bench b;
  b.program_window(1, 200);
  EXPECT_FALSE(b.bit(status::kParameterError));
  b.burst(300, us(1000), us(10));
  b.z_pulse(us(5000), us(10));
  b.burst(250, us(6000), us(10));
  b.run_until(us(5500));
  EXPECT_EQ(b.module->position(), 0);
  EXPECT_FALSE(b.module->window_open());
  b.run_until(us(6000) - 1_ns);
  EXPECT_FALSE(b.module->window_open());
  b.run_until(us(6000));
  EXPECT_TRUE(b.module->window_open());
  EXPECT_EQ(b.module->position(), 1);
  b.run_until(us(7990) - 1_ns);
  EXPECT_TRUE(b.module->window_open());
  b.run_until(us(7990));
  EXPECT_FALSE(b.module->window_open());
}

// [I] Z outside mode 2 is ignored (digest §2.1).
TEST(Amci4501Mode2, IndexIgnoredInModeOne) {
  Bench b;
  b.burst(500, us(1000), us(10));
  b.z_pulse(us(7000), us(10));
  b.run_until(8_ms);
  EXPECT_EQ(b.module->position(), 500);
}

// W18 (L114): mode 2 velocity is word 5, counts per 50 ms, and reads 0 when B leads A.
// F(10000, 40,005 us, 10 us) covers (50, 100] ms fully: 5,000 edges. The reverse run
// R(10000, 140,005 us, 10 us) covers (150, 200] ms: reads 0.
TEST(Amci4501Mode2, VelocityIsZeroInReverse) {
  Bench b;
  b.program_window(60000, 65000);
  b.burst(10000, us(40005), us(10));
  b.run_until(100_ms);
  EXPECT_EQ(b.word(5), 5000);
  b.burst(-10000, us(140005), us(10));
  b.run_until(200_ms);
  EXPECT_EQ(b.word(5), 0);
}

// L93: the encoder stops inside the window -> Time Out after the timeout, no data.
TEST(Amci4501Mode2, EncoderStopsInWindowTimesOut) {
  Bench b;
  b.program_window(100, 300, 50);
  b.burst(150, us(1000), us(10)); // window opens at 1,990 us, timeout at 51,990 us
  b.run_until(us(51990) - 1_ns);
  EXPECT_FALSE(b.bit(status::kTimeout));
  b.run_until(us(51990));
  EXPECT_TRUE(b.bit(status::kTimeout));
  EXPECT_FALSE(b.module->window_open());
  EXPECT_FALSE(b.bit(status::kNewValue));
}

// L12: "The cycle output will match the latch input during the first two transitions of the
// latch input in the enable window. The cycle output will turn off at the end of the enable
// window"; a Time Out ends the window, the cycle abandoned (L93, L119). The output answers a
// Latch edge one throughput (125 us, L281) after it, so an answer to an edge 125 us or less
// before the Time Out would land at or after the window's end: it is dropped, the output stays
// off.
// Window 100..300 opens at 1,990 us and the encoder stops inside it; timeout 5 ms: Time Out at
// T = 6,990 us. A 1 ms Latch pulse, its leading edge swept across T.
TEST(Amci4501Mode2, TimeoutDropsALeadingEdgesAnswerStillOnItsWay) {
  struct Case {
    std::int64_t lead_us;
    std::vector<std::pair<std::int64_t, bool>> edges; // the Cycle Output's (us, on)
  };
  const std::vector<Case> cases{
      {5990, {{6115, true}, {6990, false}}}, // well before: on 125 us later, off at T
      {6864, {{6989, true}, {6990, false}}}, // 126 us before: on 1 us before T
      {6865, {}},                            // 125 us before: would land at T
      {6945, {}},                            // 45 us before (the audit's case)
      {6990, {}},                            // at T: taken before the timeout (in the window), answer dropped
      {6991, {}},                            // after T: no window
  };
  for (const Case& c : cases) {
    Bench b;
    b.program_window(100, 300, 5);
    b.burst(150, us(1000), us(10));
    b.latch_pulse(us(c.lead_us), 1_ms);
    b.run_until(20_ms);
    EXPECT_TRUE(b.bit(status::kTimeout)) << c.lead_us;
    EXPECT_FALSE(b.bit(status::kNewValue)) << c.lead_us;
    EXPECT_FALSE(b.module->cycle_output_on()) << c.lead_us;
    std::vector<std::pair<std::int64_t, bool>> seen;
    for (const CapturedEdge& e : b.cycle_edges) seen.emplace_back(e.time.count() / 1000, e.on);
    EXPECT_EQ(seen, c.edges) << "leading edge at " << c.lead_us << " us";
  }
}

// The same for a trailing edge: an OFF still on its way at the Time Out is overtaken by the
// window's end (L12), at T. A pulse from T - 1 ms; its trailing edge 126 us, 125 us and 45 us
// before T (same window and timeout as above).
TEST(Amci4501Mode2, TimeoutTurnsTheOutputOffAtOnce) {
  const Nanos t_out = us(6990);
  for (const auto& [trail, off_at] : {std::pair{t_out - us(126), t_out - 1_us},
                                      std::pair{t_out - us(125), t_out}, std::pair{t_out - us(45), t_out}}) {
    Bench b;
    b.program_window(100, 300, 5);
    b.burst(150, us(1000), us(10));
    b.latch_pulse(t_out - 1_ms, trail - (t_out - 1_ms));
    b.run_until(20_ms);
    ASSERT_EQ(b.cycle_edges.size(), 2u) << trail.count();
    EXPECT_EQ(b.cycle_edges[0].time, t_out - us(875));
    EXPECT_EQ(b.cycle_edges[1].time, off_at) << trail.count();
    EXPECT_FALSE(b.cycle_edges[1].on);
  }
}

// L119 with L114: mode 2's velocity word 5 is frozen while Time Out is set. Window
// 100..300, timeout 50 ms; F(150, 1,000 us, 10 us) opens the window at 1,990 us and stops
// inside it: Time Out at 51,990 us. F(10000, 60,005 us, 10 us) runs 60.005-160.0 ms: the
// window ending at 50 ms (150 edges, before Time Out) is written, the one ending at 100 ms
// (4,000 edges) is not. Cleared at 120 ms (L154): the window ending at 150 ms holds 5,000.
TEST(Amci4501Mode2, TimeoutFreezesTheVelocityWordUntilCleared) {
  Bench b;
  b.program_window(100, 300, 50);
  b.burst(150, us(1000), us(10));
  b.burst(10000, us(60005), us(10));
  b.run_until(50_ms);
  EXPECT_EQ(b.word(5), 150);
  b.run_until(us(51990));
  ASSERT_TRUE(b.bit(status::kTimeout));
  b.run_until(100_ms);
  EXPECT_EQ(b.word(5), 150);
  b.run_until(120_ms);
  b.module->write_output(0, control::kClearError);
  b.run_until(150_ms - 1_ns);
  EXPECT_EQ(b.word(5), 150);
  b.run_until(150_ms);
  EXPECT_EQ(b.word(5), 5000);
}

// L115 / A12: an L value above 32,767 counts saturates at 32,767 (MODEL) and is recorded.
TEST(Amci4501Mode2, LatchCountsCapAt32767) {
  Bench b;
  b.program_window(1, 40000);
  b.burst(33000, us(1000), us(4)); // P = 33,000 by 132,996 us
  b.latch_pulse(us(134000), us(200));
  b.run_until(140_ms);
  b.burst(7000, us(141000), us(4)); // P reaches 40,000
  b.run_until(200_ms);
  EXPECT_EQ(b.word(1), 32767);
  EXPECT_GE(b.module->count_overflows(), 1u);
}

// Same-instant order (README): at one instant the encoder edge first, then Start/Latch edges,
// then the timeout if the cycle has not ended. The bench's encoder: 100 us per edge from
// 1,000 us, so edge k (P = k) at 1,000 + (k - 1)·100 us. Window on 100 opens at 10,900 us.

// L12: "The measurement cycle is complete when the encoder position reaches the off
// setpoint"; L93: Time Out only if the cycle "does not end within the programmed timeout
// time" (inclusive, as in modes 1/3/4). Timeout 10 ms (T = 20,900 us); off 199/200/201 close the
// window at T - 100 us / T / T + 100 us. The edges after 16 ms are scheduled after the timer
// (as the rig's encoder stream is), so scheduling order cannot decide the tie. Latch
// 12,050-13,050 us: L1 = 111 - 100 = 11, L2 = 121 - 100 = 21.
TEST(Amci4501Mode2, WindowClosingAtTheTimeoutEndsWithinIt) {
  for (const auto& [off, timed_out] :
       {std::pair{199u, false}, std::pair{200u, false}, std::pair{201u, true}}) {
    Bench b;
    b.program_window(100, off, 10);
    b.burst(150, us(1000), us(100)); // edges 1..150, to 15,900 us
    b.latch_pulse(us(12050), 1_ms);
    b.run_until(16_ms);
    b.burst(150, us(16000), us(100)); // edges 151..300
    b.run_until(40_ms);
    EXPECT_EQ(b.bit(status::kTimeout), timed_out) << off;
    EXPECT_EQ(b.bit(status::kNewValue), !timed_out) << off;
    EXPECT_EQ(b.word(1), timed_out ? 0 : 11) << off;
    EXPECT_EQ(b.word(2), timed_out ? 0 : 21) << off;
  }
}

// The window is half-open in time, [reaching on, reaching off) (L12, L226): a Latch rising
// at the instant P reaches off (edge 200, 20,900 us) is after the window, no L1 and no Cycle
// Output pulse; 1 ns earlier it is inside (L1 = 199 - 100 = 99; the output copies it and is
// forced off at window end + 125 us, L12, L281). Either scheduling order gives the same.
TEST(Amci4501Mode2, LatchAtTheWindowsCloseIsAfterIt) {
  const Nanos close = us(20900);
  struct Case {
    Nanos lead;
    std::uint16_t l1;
    std::vector<std::pair<Nanos, bool>> edges; // the Cycle Output's
  };
  const std::vector<Case> cases{
      {close - 1_ns, 99, {{close - 1_ns + us(125), true}, {close + us(125), false}}},
      {close, 0, {}},
      {close + 1_ns, 0, {}},
  };
  for (const Case& c : cases) {
    for (const bool latch_first : {true, false}) {
      Bench b;
      b.program_window(100, 200, 1000);
      if (latch_first) b.latch_pulse(c.lead, us(300));
      b.burst(300, us(1000), us(100));
      if (!latch_first) b.latch_pulse(c.lead, us(300));
      b.run_until(40_ms);
      EXPECT_TRUE(b.bit(status::kNewValue));
      EXPECT_EQ(b.word(1), c.l1) << c.lead.count() << " latch first " << latch_first;
      EXPECT_EQ(b.word(2), 0) << c.lead.count(); // the trailing edge is after the window
      std::vector<std::pair<Nanos, bool>> seen;
      for (const CapturedEdge& e : b.cycle_edges) seen.emplace_back(e.time, e.on);
      EXPECT_EQ(seen, c.edges) << c.lead.count() << " latch first " << latch_first;
    }
  }
}

// The same at the other end and for a trailing edge: a Latch rising at the instant P reaches
// on (edge 100, 10,900 us) is inside (L1 = 0); 1 ns earlier it was already active when the
// window opened (not counted, [I] A14). A trailing edge at the instant P reaches off is
// after the window (L2 = 0, output forced off at window end, L12); 1 ns earlier it is L2 = 99.
TEST(Amci4501Mode2, LatchEdgesAtTheWindowsEndsFollowTheHalfOpenWindow) {
  const Nanos open = us(10900);
  const Nanos close = us(20900);
  for (const auto& [lead, l1] : {std::pair{open - 1_ns, 0}, std::pair{open, 0}, std::pair{open + 1_ns, 0}}) {
    Bench b;
    b.program_window(100, 200, 1000);
    b.latch_pulse(lead, us(450)); // trailing edge at edge 104.5: L2 = 4 when counted
    b.burst(300, us(1000), us(100));
    b.run_until(40_ms);
    const bool counted = lead >= open;
    EXPECT_EQ(b.word(1), l1) << lead.count();
    EXPECT_EQ(b.word(2), counted ? 4 : 0) << lead.count();
    EXPECT_EQ(b.cycle_edges.size(), counted ? 2u : 0u) << lead.count();
  }
  for (const auto& [trail, l2] :
       {std::pair{close - 1_ns, 99}, std::pair{close, 0}, std::pair{close + 1_ns, 0}}) {
    Bench b;
    b.program_window(100, 200, 1000);
    b.burst(300, us(1000), us(100));
    b.latch_pulse(us(15050), trail - us(15050)); // L1 = 141 - 100 = 41
    b.run_until(40_ms);
    EXPECT_EQ(b.word(1), 41) << trail.count();
    EXPECT_EQ(b.word(2), l2) << trail.count();
    ASSERT_EQ(b.cycle_edges.size(), 2u) << trail.count();
    EXPECT_EQ(b.cycle_edges[1].time, std::min(trail, close) + us(125)) << trail.count();
  }
}

} // namespace
} // namespace hilrig::models::amci4501::test
