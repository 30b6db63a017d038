// Fault variants: each one named, selectable from its name, and different from the
// correct model on an input where the spec fixes the answer.
#include "amci4501_rig.hpp"

namespace hilrig::models::amci4501::test {
namespace {

Params with(Variant v) {
  Params p;
  p.variant = v;
  return p;
}

TEST(Amci4501Variants, NamesRoundTrip) {
  for (const auto& v : kVariantNames) {
    EXPECT_EQ(variant_from_string(v.name), v.variant);
    EXPECT_EQ(to_string(v.variant), v.name);
  }
  EXPECT_EQ(variant_from_string("nominal"), Variant::Correct);
  EXPECT_FALSE(variant_from_string("x4_counting").has_value());
}

// Mode 1, one Start/Latch cycle around 100 counts (as CycleOutputSpansStartToLatch).
struct Mode1Run {
  std::vector<CapturedEdge> cycle;
  std::uint16_t value;
};
Mode1Run mode1(Variant v) {
  Bench b{with(v)};
  b.start_pulse(us(1000), us(500));
  b.burst(100, us(2000), us(10));
  b.latch_pulse(us(5000), us(500));
  b.run_until(10_ms);
  return {b.cycle_edges, b.word(1)};
}

// Throughput 125 us (L281): the correct Cycle Output turns on at 1,125 us; the late
// variant at 1,250 us, outside the [t, t + 125] window of examples §0.6.
TEST(Amci4501Variants, LateOutputsMissTheThroughputWindow) {
  const Mode1Run good = mode1(Variant::Correct);
  const Mode1Run late = mode1(Variant::LateOutputs);
  ASSERT_EQ(late.cycle.size(), 2u);
  EXPECT_EQ(good.cycle[0].time, us(1125));
  EXPECT_EQ(late.cycle[0].time, us(1250));
  EXPECT_GT(late.cycle[0].time - us(1000), us(125));
}

// X4 (L7): 100 edges are 100 counts; X2 counts only A's edges: 50.
TEST(Amci4501Variants, X2CountsHalf) {
  EXPECT_EQ(mode1(Variant::Correct).value, 100);
  EXPECT_EQ(mode1(Variant::X2Counting).value, 50);
}

std::pair<std::uint16_t, std::uint16_t> mode3_time(Variant v) {
  Bench b{with(v)};
  b.program_mode(3);
  b.start_pulse(us(1000), us(300));
  b.latch_pulse(us(13345), us(300));
  b.run_until(20_ms);
  return {b.word(1), b.word(2)};
}

// W3: 12,345 us -> 12 / 345. Wrong unit (10 us): 1 / 234. Off by one tick: 12 / 346.
TEST(Amci4501Variants, TimeUnitAndTickErrors) {
  EXPECT_EQ(mode3_time(Variant::Correct), std::make_pair(std::uint16_t{12}, std::uint16_t{345}));
  EXPECT_EQ(mode3_time(Variant::TimeWrongUnit), std::make_pair(std::uint16_t{1}, std::uint16_t{234}));
  EXPECT_EQ(mode3_time(Variant::TimeOffByOne), std::make_pair(std::uint16_t{12}, std::uint16_t{346}));
}

// W14: with the filter ignored the 5,999 us Latch becomes L2: TM2 = 3,001 not 3,000.
TEST(Amci4501Variants, Mode4FilterIgnored) {
  const auto tm2 = [](Variant v) {
    Bench b{with(v)};
    b.program_mode(4);
    b.start_pulse(us(1000), us(300));
    b.latch_pulse(us(5000), us(300));
    b.latch_pulse(us(5999), us(1));
    b.latch_pulse(us(6000), us(300));
    b.start_pulse(us(9000), us(300));
    b.run_until(12_ms);
    return 1000 * b.word(3) + b.word(4);
  };
  EXPECT_EQ(tm2(Variant::Correct), 3000);
  EXPECT_EQ(tm2(Variant::Mode4FilterIgnored), 3001);
}

// W10: six unacknowledged cycles raise No Response, except in the faulty variant.
TEST(Amci4501Variants, NoResponseNeverRaised) {
  const auto raised = [](Variant v) {
    Bench b{with(v)};
    for (int k = 1; k <= 6; ++k) {
      b.start_pulse(milliseconds(10 * k), us(200));
      b.latch_pulse(milliseconds(10 * k + 5), us(200));
    }
    b.run_until(70_ms);
    return b.bit(status::kNoResponse);
  };
  EXPECT_TRUE(raised(Variant::Correct));
  EXPECT_FALSE(raised(Variant::NoResponseNeverRaised));
}

} // namespace
} // namespace hilrig::models::amci4501::test
