// Production counters (spec §4.12, manual L1185-L1226): part-cycle events at the increment
// position, multiplier/divisor, batch modes, Good Part, Machine Revolutions, overflow outputs
// and the 999,999,999 roll-over. The engine is driven directly with GMP steps.
#include <cstdint>

#include <gtest/gtest.h>

#include "models/ans1/production_counters.hpp"

namespace hilrig::models::ans1 {
namespace {

// Moves GMP forward one count at a time through `cycles` whole machine cycles (FSC 360),
// starting and ending at `start`.
void run_cycles(ProductionCounters& c, int cycles, std::uint16_t start = 10, bool dp_fault = false) {
  for (int k = 1; k <= cycles * 360; ++k) {
    c.update(static_cast<std::uint16_t>((start + k) % 360), dp_fault);
  }
}

ProductionCounters primed(const ProductionSetup& s, std::uint16_t start = 10) {
  ProductionCounters c;
  c.configure(s, 360);
  c.update(start, false);
  return c;
}

TEST(ProductionCounters, PartCycleCountsEachForwardPassOfTheIncrementPosition) {
  ProductionSetup s;
  s.increment_position = 90;
  ProductionCounters c = primed(s);
  run_cycles(c, 3);
  EXPECT_EQ(c.value(CounterId::PartCycle), 3U);
  EXPECT_EQ(c.value(CounterId::Revolutions), 3U); // three passes through GMP 0 (L1215)
  EXPECT_EQ(c.value(CounterId::GoodPart), 3U);
  EXPECT_EQ(c.value(CounterId::Batch1), 3U);
}

TEST(ProductionCounters, EventHappensWhenGmpReachesTheIncrementPosition) {
  ProductionSetup s;
  s.increment_position = 90;
  ProductionCounters c = primed(s, 88);
  EXPECT_FALSE(c.update(89, false));
  EXPECT_TRUE(c.update(90, false));
  EXPECT_FALSE(c.update(91, false));
  EXPECT_EQ(c.value(CounterId::PartCycle), 1U);
}

TEST(ProductionCounters, StepsOverSeveralCountsStillCount) {
  // A fast press moves several counts per scan: 85 -> 95 passes 90.
  ProductionSetup s;
  s.increment_position = 90;
  ProductionCounters c = primed(s, 85);
  EXPECT_TRUE(c.update(95, false));
}

TEST(ProductionCounters, ReverseMotionCountsNothing) {
  // [MODEL A53]: backing through 0 and the increment position counts neither.
  ProductionSetup s;
  ProductionCounters c = primed(s, 5);
  for (int p = 4; p >= 0; --p) c.update(static_cast<std::uint16_t>(p), false);
  c.update(359, false);
  c.update(358, false);
  EXPECT_EQ(c.value(CounterId::PartCycle), 0U);
  EXPECT_EQ(c.value(CounterId::Revolutions), 0U);
}

TEST(ProductionCounters, MultiplierAndDivisorScaleThePartCycleCount) {
  // Part Cycle = revolutions * M / D (L1193): M 3, D 2 over 5 cycles -> floor(15/2) = 7.
  ProductionSetup s;
  s.multiplier = 3;
  s.divisor = 2;
  ProductionCounters c = primed(s);
  run_cycles(c, 5);
  EXPECT_EQ(c.value(CounterId::PartCycle), 7U);
  EXPECT_EQ(c.value(CounterId::Revolutions), 5U);
  EXPECT_EQ(c.value(CounterId::Batch1), 7U); // batches follow the part-cycle count
}

TEST(ProductionCounters, DieFaultCyclesAreNotGoodPartsNorMode1Batches) {
  // L1201-L1211: Good Part and a mode-1 batch skip cycles with a DP fault; mode-0 batches and
  // the part-cycle counter do not.
  ProductionSetup s;
  s.counters[2].only_good_cycles = true; // Batch 2 in mode 1
  ProductionCounters c = primed(s);
  run_cycles(c, 2);
  run_cycles(c, 1, 10, /*dp_fault=*/true);
  EXPECT_EQ(c.value(CounterId::PartCycle), 3U);
  EXPECT_EQ(c.value(CounterId::Batch1), 3U);
  EXPECT_EQ(c.value(CounterId::Batch2), 2U);
  EXPECT_EQ(c.value(CounterId::GoodPart), 2U);
}

TEST(ProductionCounters, Mode1OverflowOutputIsActiveForTheCycleAfterTheLimit) {
  // L1224: active when the count reaches the limit, inactive at the start of the next cycle.
  ProductionSetup s;
  s.counters[1] = CounterSetup{14, OverflowMode::ActiveUntilNextCycle, false, 2};
  ProductionCounters c = primed(s);
  run_cycles(c, 1);
  EXPECT_EQ(c.overflow_output_levels(), 0);
  run_cycles(c, 1); // count 2 == limit
  EXPECT_TRUE(c.overflowed(CounterId::Batch1));
  EXPECT_EQ(c.overflow_output_levels(), 1U << 13);
  EXPECT_EQ(c.overflow_state_mask(CounterId::Batch1), 1U << 13);
  EXPECT_EQ(c.overflow_output_mask(), 1U << 13);
  run_cycles(c, 1);
  EXPECT_EQ(c.overflow_output_levels(), 0);
}

TEST(ProductionCounters, Mode2OverflowOutputTogglesEachTimeTheLimitIsReached) {
  ProductionSetup s;
  s.counters[0] = CounterSetup{3, OverflowMode::Toggle, false, 2};
  ProductionCounters c = primed(s);
  run_cycles(c, 2);
  EXPECT_EQ(c.overflow_output_levels(), 1U << 2);
  run_cycles(c, 5);
  EXPECT_EQ(c.overflow_output_levels(), 1U << 2); // not reached again: the count went past it
  c.preset(CounterId::PartCycle, 0);
  run_cycles(c, 2);
  EXPECT_EQ(c.overflow_output_levels(), 0); // reached a second time: toggled back
}

TEST(ProductionCounters, CountsRollOverFrom999999999To0) {
  // W-15: the maximum is 999,999,999 (0x3B9AC9FF) [MODEL A30: odometer roll-over].
  ProductionSetup s;
  ProductionCounters c = primed(s);
  c.preset(CounterId::PartCycle, kCounterMax);
  c.preset(CounterId::Revolutions, kCounterMax - 1);
  run_cycles(c, 1);
  EXPECT_EQ(c.value(CounterId::PartCycle), 0U);
  EXPECT_EQ(c.value(CounterId::Revolutions), kCounterMax);
  run_cycles(c, 1);
  EXPECT_EQ(c.value(CounterId::PartCycle), 1U);
  EXPECT_EQ(c.value(CounterId::Revolutions), 0U);
}

TEST(ProductionCounters, PresetSetsTheCountAndCountingContinuesFromIt) {
  ProductionSetup s;
  ProductionCounters c = primed(s);
  c.preset(CounterId::Batch3, 40'000);
  run_cycles(c, 2);
  EXPECT_EQ(c.value(CounterId::Batch3), 40'002U);
}

} // namespace
} // namespace hilrig::models::ans1
