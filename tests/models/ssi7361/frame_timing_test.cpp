// The 7361 as SSI master on the wire: clock timing (M-22, digest §2.1, §6), the sampling
// instant (§2.1 [MODEL]) and what it reads with no transducer (M-03, §4).

#include <gtest/gtest.h>

#include <vector>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

// The clock edges the module drove, as a reader on the clock line saw them.
struct ClockProbe {
  explicit ClockProbe(Rig& rig) {
    rig.clock_line().reader().on_edge([this](const Edge& e) { edges.push_back(e); });
  }
  std::vector<Edge> edges;
};

// Checks the frames starting at `first` (F1 times first, first + tint, ...): 25 falling and
// 25 rising edges, F_j at (j-1)T and R_k at (k-1/2)T, the clock high between frames.
void expect_frames(const std::vector<Edge>& edges, Nanos first, Nanos period, Nanos tint, int frames) {
  std::vector<Edge> from;
  for (const Edge& e : edges) {
    if (e.time >= first && e.time < first + tint * frames) from.push_back(e);
  }
  ASSERT_EQ(from.size(), static_cast<std::size_t>(50 * frames));
  for (int f = 0; f < frames; ++f) {
    const Nanos f1 = first + tint * f;
    for (int k = 1; k <= 25; ++k) {
      const Edge& fall = from[static_cast<std::size_t>(f * 50 + 2 * (k - 1))];
      const Edge& rise = from[static_cast<std::size_t>(f * 50 + 2 * (k - 1) + 1)];
      EXPECT_EQ(fall, (Edge{f1 + period * (k - 1), Level::Low})) << "frame " << f << " F" << k;
      EXPECT_EQ(rise, (Edge{f1 + period * (k - 1) + period / 2, Level::High})) << "frame " << f << " R" << k;
    }
    if (f + 1 < frames) {
      // TIDL from the last falling edge F25 to the next F1 (digest §2.1: TINT - TIDL = 24 T).
      const Nanos f25 = from[static_cast<std::size_t>(f * 50 + 48)].time;
      const Nanos next_f1 = from[static_cast<std::size_t>((f + 1) * 50)].time;
      EXPECT_EQ(next_f1 - f25, tint - period * 24);
    }
  }
}

TEST(Ssi7361FrameTiming, M22_125kHzFramesEvery500usWithTidl308us) {
  Rig rig;
  ClockProbe probe(rig);
  rig.run_until(2_ms - 1_ns); // the fifth frame starts at 2 ms
  // T = 8 us at 125 kHz; TINT 500 us, TIDL = 500 - 24*8 = 308 us (L1096-1098).
  expect_frames(probe.edges, 0_us, 8_us, 500_us, 4);
  EXPECT_EQ(500_us - 8_us * 24, 308_us);
  EXPECT_TRUE(is_high(rig.clock_line().level())); // idle high after R25
}

TEST(Ssi7361FrameTiming, M22_500kHzFramesEvery250usWithTidl202us) {
  Rig rig;
  ClockProbe probe(rig);
  rig.run_until(1_ms); // the frame at 1.000 ms has started at 125 kHz
  // Defaults (M-21: M=1, N=24) with the SSIClk bit: 0x8118.
  ASSERT_EQ(rig.program(qbit::kFormat, {.format = format_word(1, 24, false, false, true)}), qbit::kTransmit);
  rig.run_until(3_ms);
  // The frame running at the change finishes at 125 kHz; from F1 = 1.5 ms on: T = 2 us,
  // TINT 250 us, TIDL = 250 - 24*2 = 202 us.
  expect_frames(probe.edges, 1500_us, 2_us, 250_us, 6);
}

TEST(Ssi7361FrameTiming, TwoThousandFramesPerSecondAt125kHz) {
  Rig rig;
  ClockProbe probe(rig);
  rig.run_until(100_ms - 1_ns);
  // 1 / 500 us = 2000 frames/s: 200 frames in 100 ms, 25 rising edges each (L1088).
  int rising = 0;
  for (const Edge& e : probe.edges) rising += is_high(e.level) ? 1 : 0;
  EXPECT_EQ(rising, 200 * 25);
}

TEST(Ssi7361FrameTiming, M03_NoTransducerReadsAllOnes) {
  Rig rig; // nothing drives DATA: it idles high, as the opto input reads an open line (L2178)
  rig.run_for(1_ms);
  const StatusWords w = rig.status();
  EXPECT_EQ(w[status::kRawLow], 0xFFFF);  // stream bits 10..25
  EXPECT_EQ(w[status::kRawHigh], 0x01FF); // stream bits 1..9
  EXPECT_EQ(rig.raw(), 33'554'431u);
  EXPECT_EQ(w[status::kI], 0); // no status bit: transducer faults are not detected (L260-262)
  // Defaults M=1, N=24: field = 0x1FFFFFF >> 1 = 16,777,215 (digest §4).
  EXPECT_EQ(rig.dv(), 16'777'215);
}

TEST(Ssi7361FrameTiming, NoExternalSupplyReadsAllOnesWhateverTheSensorSends) {
  Rig rig;
  rig.attach_word_sensor();
  rig.send(0x0123456);
  EXPECT_EQ(rig.raw(), 0x0123456u);
  rig.module().set_sensor_supply(false); // +24 V missing on pins 1/2 (L2182-2184)
  rig.run_for(1_ms);
  EXPECT_EQ(rig.raw(), 0x1FFFFFFu);
  EXPECT_EQ(rig.status_bits(), 0);
}

TEST(Ssi7361FrameTiming, DataStuckLowReadsZeroAndIsNotFlagged) {
  Rig rig;
  rig.attach_word_sensor();
  rig.send(0x1ABCDEF);
  rig.set_sensor_faults({.stuck = signals::SsiStuck::Low});
  rig.run_for(1_ms);
  EXPECT_EQ(rig.raw(), 0u);
  EXPECT_EQ(rig.status_bits(), 0);
}

TEST(Ssi7361FrameTiming, ReadsEveryFrameBitFromTheSlave) {
  Rig rig;
  rig.attach_word_sensor();
  for (std::uint32_t w : {0x0000000u, 0x1555555u, 0x0AAAAAAu, 0x1000001u, 0x1FFFFFEu}) {
    rig.send(w);
    EXPECT_EQ(rig.raw(), w);
  }
}

// The module samples bit k half a period after R_k (k*T after F1): a transducer whose data
// follows the clock by less than T/2 is read right; later, every bit is read one place late
// (bit k reads bit k-1; bit 1 reads the low DATA drops to at F1), i.e. raw = word >> 1.
TEST(Ssi7361FrameTiming, SamplesHalfAPeriodAfterTheRisingEdge) {
  {
    Rig rig;
    rig.attach_word_sensor(3500_ns); // T/2 = 4 us at 125 kHz
    rig.send(0x1555555);
    EXPECT_EQ(rig.raw(), 0x1555555u);
  }
  {
    Rig rig;
    rig.attach_word_sensor(4500_ns);
    rig.send(0x1555555);
    EXPECT_EQ(rig.raw(), 0x0AAAAAAu);
  }
}

TEST(Ssi7361FrameTiming, SlowTransducerFailsAt500kHzAndWorksAt125kHz) {
  // L2186-2187: a transducer too slow for 500 kHz; 1.5 us delay > T/2 = 1 us, < 4 us.
  Rig rig;
  rig.attach_word_sensor(1500_ns);
  rig.send(0x1555555);
  EXPECT_EQ(rig.raw(), 0x1555555u);
  ASSERT_EQ(rig.program(qbit::kFormat, {.format = format_word(1, 25, false, false, true)}), qbit::kTransmit);
  rig.run_for(1_ms);
  EXPECT_EQ(rig.raw(), 0x0AAAAAAu);
}

} // namespace
} // namespace hilrig::models::ssi7361::test
