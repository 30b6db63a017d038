#include "rig/rt/spsc_ring.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

using hilrig::rig::SpscRing;

TEST(SpscRing, RejectsCapacityThatIsNotAPowerOfTwo) {
  EXPECT_THROW(SpscRing<int>(3), std::invalid_argument);
  EXPECT_THROW(SpscRing<int>(1), std::invalid_argument);
  EXPECT_NO_THROW(SpscRing<int>(4));
}

TEST(SpscRing, FullRingRefusesInsteadOfOverwriting) {
  SpscRing<int> ring(4);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.push(i));
  EXPECT_FALSE(ring.push(99)); // the oldest sample must survive
  int v = -1;
  EXPECT_TRUE(ring.pop(v));
  EXPECT_EQ(v, 0);
  EXPECT_TRUE(ring.push(4)); // one slot freed
}

TEST(SpscRing, PreservesOrderAcrossWrapAround) {
  SpscRing<int> ring(8);
  int out = 0;
  for (int round = 0; round < 100; ++round) {
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(ring.push(round * 5 + k));
    for (int k = 0; k < 5; ++k) {
      ASSERT_TRUE(ring.pop(out));
      ASSERT_EQ(out, round * 5 + k);
    }
  }
  EXPECT_FALSE(ring.pop(out));
}

TEST(SpscRing, TwoThreadsTransferEveryItemInOrder) {
  SpscRing<std::uint64_t> ring(1024);
  constexpr std::uint64_t kItems = 200'000;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kItems;) {
      if (ring.push(i)) ++i;
    }
  });
  std::uint64_t expected = 0;
  std::uint64_t v = 0;
  while (expected < kItems) {
    if (ring.pop(v)) {
      ASSERT_EQ(v, expected);
      ++expected;
    }
  }
  producer.join();
}
