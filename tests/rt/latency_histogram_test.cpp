#include "rig/rt/latency_histogram.hpp"

#include <gtest/gtest.h>

#include <memory>

using namespace hilrig;
using hilrig::rig::LatencyHistogram;

TEST(LatencyHistogram, BinsAreOneMicrosecondWide) {
  auto h = std::make_unique<LatencyHistogram>();
  h->record(Nanos{999});   // 0 us bin
  h->record(Nanos{1'000}); // 1 us bin
  h->record(Nanos{1'999}); // 1 us bin
  h->record(Nanos{7'500}); // 7 us bin
  EXPECT_EQ(h->bin(0), 1U);
  EXPECT_EQ(h->bin(1), 2U);
  EXPECT_EQ(h->bin(7), 1U);
  EXPECT_EQ(h->count(), 4U);
  EXPECT_EQ(h->min(), Nanos{999});
  EXPECT_EQ(h->max(), Nanos{7'500});
  EXPECT_EQ(h->average(), Nanos{(999 + 1'000 + 1'999 + 7'500) / 4});
  EXPECT_EQ(h->last_bin(), 7U);
}

TEST(LatencyHistogram, LatencyBeyondTheLastBinIsAnOverflowNotLost) {
  auto h = std::make_unique<LatencyHistogram>();
  h->record(milliseconds(20)); // 20,000 us > 9,999 us
  EXPECT_EQ(h->overflow(), 1U);
  EXPECT_EQ(h->count(), 1U);
  EXPECT_EQ(h->max(), milliseconds(20));
}

TEST(LatencyHistogram, PercentileIsTheUpperEdgeOfTheBinReachingTheFraction) {
  auto h = std::make_unique<LatencyHistogram>();
  // 98 samples at 2 us, 2 samples at 50 us: p99 needs 99 samples, so it lands in the 50 us bin.
  for (int i = 0; i < 98; ++i) h->record(microseconds(2));
  for (int i = 0; i < 2; ++i) h->record(microseconds(50));
  EXPECT_EQ(h->percentile_us(0.50), 3U);
  EXPECT_EQ(h->percentile_us(0.98), 3U);
  EXPECT_EQ(h->percentile_us(0.99), 51U);
}
