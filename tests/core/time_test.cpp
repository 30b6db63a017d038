#include "core/time.hpp"

#include <gtest/gtest.h>

using namespace hilrig;
using namespace hilrig::literals;

TEST(Nanos, LiteralsScaleBySiPrefix) {
  EXPECT_EQ((1_us).count(), 1'000);
  EXPECT_EQ((1_ms).count(), 1'000'000);
  EXPECT_EQ((2_s).count(), 2'000'000'000);
}

TEST(Nanos, FromSecondsRoundsToNearest) {
  EXPECT_EQ(Nanos::from_seconds(1.0 / 9600.0 * 10).count(), 1'041'667); // one 8N1 byte at 9600
  EXPECT_EQ(Nanos::from_seconds(-1.4e-9).count(), -1);
  EXPECT_EQ(Nanos::from_seconds(2.5e-9).count(), 3);
}

TEST(Nanos, ArithmeticAndOrdering) {
  EXPECT_EQ(3_ms - 1_ms, 2_ms);
  EXPECT_EQ(4_us * 3, 12_us);
  EXPECT_EQ(1_s / 1_ms, 1000);
  EXPECT_LT(-1_ns, 0_ns);
  EXPECT_EQ(7_us % 2_us, 1_us);
}
