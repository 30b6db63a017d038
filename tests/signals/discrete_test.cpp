// Discrete inputs: level changes, pulse trains, and contact bounce (reproducible per seed,
// inside its window).

#include "signals/discrete_bounce.hpp"
#include "signals/discrete_input.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

TEST(DiscreteSignal, LevelChangesAtTimes) {
  DiscreteSignal s(Level::Low);
  s.set(1_ms, Level::High).set(2_ms, Level::High).set(3_ms, Level::Low);
  ASSERT_EQ(s.edges().size(), 2U); // setting the same level adds no edge
  EXPECT_EQ(s.level_at(999_us), Level::Low);
  EXPECT_EQ(s.level_at(1_ms), Level::High);
  EXPECT_EQ(s.level_at(3_ms), Level::Low);
  EXPECT_THROW(s.set(2_ms, Level::High), std::invalid_argument);
}

TEST(DiscreteSignal, PulseTrain) {
  // 5 pulses of 10 us every 100 us from 1 ms: the last ends at 1 ms + 400 + 10 us.
  DiscreteSignal s;
  s.pulse_train(1_ms, 100_us, 10_us, 5);
  ASSERT_EQ(s.edges().size(), 10U);
  EXPECT_EQ(s.level_at(1'005_us), Level::High);
  EXPECT_EQ(s.level_at(1'015_us), Level::Low);
  EXPECT_EQ(s.level_at(1'405_us), Level::High);
  EXPECT_EQ(s.edges().back().time, 1'410_us);
  EXPECT_EQ(s.edges().back().level, Level::Low);
}

TEST(ContactBounce, GivenGapsPlaceEveryEdge) {
  // Two bounces, gaps 100/200/300/400 us: touch at 5 ms, open 5.1, touch 5.3, open 5.6,
  // settle 6.0 ms = 5 ms + the 1 ms window.
  ContactBounce b{1_ms, 2, {100_us, 200_us, 300_us, 400_us}};
  const auto e = bounce_edges(5_ms, Level::High, b);
  ASSERT_EQ(e.size(), 5U);
  EXPECT_EQ(e[0], (Edge{5_ms, Level::High}));
  EXPECT_EQ(e[1], (Edge{5'100_us, Level::Low}));
  EXPECT_EQ(e[2], (Edge{5'300_us, Level::High}));
  EXPECT_EQ(e[3], (Edge{5'600_us, Level::Low}));
  EXPECT_EQ(e[4], (Edge{6_ms, Level::High}));
  b.widths.pop_back();
  EXPECT_THROW(static_cast<void>(bounce_edges(5_ms, Level::High, b)), std::invalid_argument);
  ContactBounce too_long{1_ms, 1, {600_us, 600_us}};
  EXPECT_THROW(static_cast<void>(bounce_edges(5_ms, Level::High, too_long)), std::invalid_argument);
}

TEST(ContactBounce, SeededBounceIsReproducibleAndStaysInItsWindow) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const std::size_t bounces = 1 + seed % 7;
    const ContactBounce b{2_ms, bounces, {}, seed, 5_us};
    const auto e1 = bounce_edges(10_ms, Level::Low, b);
    const auto e2 = bounce_edges(10_ms, Level::Low, b);
    EXPECT_EQ(e1, e2);
    ASSERT_EQ(e1.size(), 2 * bounces + 1);
    EXPECT_EQ(e1.front().time, 10_ms);
    EXPECT_EQ(e1.back().level, Level::Low);
    EXPECT_LE(e1.back().time, 12_ms);
    for (std::size_t i = 1; i < e1.size(); ++i) {
      EXPECT_GE(e1[i].time - e1[i - 1].time, 5_us);
      EXPECT_NE(e1[i].level, e1[i - 1].level);
    }
  }
  const ContactBounce a{2_ms, 3, {}, 7, 1_ns};
  ContactBounce b = a;
  b.seed = 8;
  EXPECT_NE(draw_bounce_gaps(a), draw_bounce_gaps(b));
}

TEST(DiscreteSignal, BounceToSettlesAtTheTarget) {
  DiscreteSignal s(Level::Low);
  s.bounce_to(1_ms, Level::High, ContactBounce{500_us, 4, {}, 99, 10_us});
  EXPECT_EQ(s.edges().size(), 9U);
  EXPECT_EQ(s.level_at(1_ms), Level::High);
  EXPECT_EQ(s.level_at(1'500_us), Level::High);
  EXPECT_EQ(s.level(), Level::High);
  EXPECT_THROW(s.bounce_to(2_ms, Level::High, ContactBounce{500_us, 1, {}, 1}), std::logic_error);
}
