// Edge-rate limits against the AMCI 4501's 250 kHz maximum input frequency (spec
// amci4501.md 2.1, L271). A channel's frequency is counts/s / 4 = turns/s x lines.

#include "signals/edge_rate.hpp"
#include "signals/move_builders.hpp"

#include <gtest/gtest.h>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::signals;

TEST(EdgeRate, RampReportsWhenAndHowFastItCrossesTheLimit) {
  // 1,024 lines, ramp from rest to 20,000 RPM (333.33 turns/s) in 1 s. 250 kHz per
  // channel is 250,000 / 1,024 = 244.140625 turns/s, reached at 244.140625 / 333.33 s =
  // 0.732421875 s. Peak: 333.33 x 1,024 = 341,333.33 Hz per channel.
  QuadratureEncoder enc; // 1,024 lines, profile in turns
  MotionProfile p;
  p.accelerate(1'000.0 / 3.0, 1_s);
  const auto v = check_edge_rate(p, enc, 250e3, RateLimitAction::Warn);
  ASSERT_EQ(v.size(), 1U);
  EXPECT_EQ(v[0].segment, 0U);
  EXPECT_EQ(v[0].time, 732'421'875_ns);
  EXPECT_NEAR(v[0].channel_hz, 341'333.33, 0.01);
  EXPECT_NEAR(v[0].count_rate, 1'365'333.33, 0.01);
}

TEST(EdgeRate, FailThrowsWithTheFirstViolation) {
  QuadratureEncoder enc;
  MotionProfile p;
  constant_speed(p, 100.0, 1_ms); // 102.4 kHz: fine
  constant_speed(p, 300.0, 1_ms); // 307.2 kHz from t = 1 ms
  try {
    check_edge_rate(p, enc, 250e3, RateLimitAction::Fail);
    FAIL() << "expected EdgeRateError";
  } catch (const EdgeRateError& e) {
    EXPECT_EQ(e.violation.time, 1_ms);
    EXPECT_NEAR(e.violation.channel_hz, 307'200.0, 1e-6);
    EXPECT_NE(std::string(e.what()).find("307200.0 Hz"), std::string::npos);
  }
}

TEST(EdgeRate, WithinTheLimitReportsNothing) {
  // The conservative reading of 250 kHz as the X4 count rate: 62.5 kHz per channel.
  // 1,024 lines at 3,600 RPM = 61.44 kHz per channel: inside even that.
  QuadratureEncoder enc;
  MotionProfile p;
  trapezoid_move(p, 20.0, MoveLimits{60.0, 600.0, 600.0});
  EXPECT_TRUE(check_edge_rate(p, enc, 62.5e3, RateLimitAction::Fail).empty());
  // Above 60 kHz (58.59375 turns/s) in all three segments: the ramp crosses it at
  // 58.59375 / 600 s = 97.65625 ms, the cruise is above it, the brake starts above it.
  const auto v = find_edge_rate_violations(p, enc, 60e3);
  ASSERT_EQ(v.size(), 3U);
  EXPECT_NEAR(static_cast<double>(v[0].time.count()), 97'656'250.0, 1.0);
  EXPECT_EQ(v[1].time, 100_ms);
}

TEST(EdgeRate, DecelerationFromAboveTheLimitIsReportedAtItsStart) {
  QuadratureEncoder enc;
  MotionProfile p(0.0, 5_ms);
  constant_speed(p, 300.0, 1_ms);
  p.accelerate(-3e5, 1_ms); // 300 -> 0 turns/s
  const auto v = find_edge_rate_violations(p, enc, 250e3);
  ASSERT_EQ(v.size(), 2U);
  EXPECT_EQ(v[1].time, 6_ms);
  EXPECT_NEAR(v[1].channel_hz, 307'200.0, 1e-6);
}
