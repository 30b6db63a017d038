// Global Machine Speed (spec §4.2): the 14.6 ms exponential filter and its default.
#include <gtest/gtest.h>

#include <cmath>

#include "models/ans1/enable.hpp"
#include "models/ans1/position_setup.hpp"
#include "models/ans1/speed.hpp"

namespace hilrig::models::ans1 {
namespace {

TEST(Ans1Speed, W12DefaultFilterCoefficientIs0625) {
  const PositionSetup defaults;
  EXPECT_EQ(defaults.rpm_filter, 40960);
  EXPECT_DOUBLE_EQ(filter_coefficient(40960), 0.625); // 40960 / 65536
  EXPECT_DOUBLE_EQ(filter_coefficient(0), 0.0);       // no filtering
}

TEST(Ans1Speed, FilterStepIsTheManualsRecurrence) {
  // S_t = k S_{t-1} + (1 - k) X_t with k = 0.625: from 0 towards 100, 37.5 then 60.9375.
  double s = filter_step(0.0, 100.0, 40960);
  EXPECT_DOUBLE_EQ(s, 37.5);
  s = filter_step(s, 100.0, 40960);
  EXPECT_DOUBLE_EQ(s, 37.5 * 0.625 + 37.5);
  // k = 0: the measurement passes straight through.
  EXPECT_DOUBLE_EQ(filter_step(55.0, -20.0, 0), -20.0);
}

TEST(Ans1Speed, MeasuredSpeedIsCyclesPerMinute) {
  // 4096 counts (one cycle of CPC 4096) in 14.6 ms = 1 / 0.0146 cycles/s = 4109.589 RPM.
  EXPECT_NEAR(measured_rpm(4096, 4096, microseconds(14'600)), 60.0 / 0.0146, 1e-9);
  // CPC 2048: the same counts are two cycles.
  EXPECT_NEAR(measured_rpm(4096, 2048, microseconds(14'600)), 2 * 60.0 / 0.0146, 1e-9);
  // Reverse: negative.
  EXPECT_LT(measured_rpm(-10, 4096, microseconds(14'600)), 0.0);
}

TEST(Ans1Speed, FilterConvergesGeometrically) {
  // After n updates from 0 at a constant X: S = X (1 - k^n). n = 10, k = 0.625: 0.99091.
  SpeedFilter f;
  // 100 RPM at CPC 4000 over 15 ms is 100 counts exactly: 100/4000 cycles / 0.015 s * 60.
  for (int i = 0; i < 10; ++i) {
    f.update(100, 4000, microseconds(15'000), 40960);
  }
  EXPECT_NEAR(f.value(), 100.0 * (1.0 - std::pow(0.625, 10)), 1e-9);
  EXPECT_EQ(f.reported(), 99);
}

TEST(Ans1Speed, ReportedSpeedRoundsAndSaturates) {
  EXPECT_EQ(reported_rpm(99.5), 100);
  EXPECT_EQ(reported_rpm(-99.5), -100);
  EXPECT_EQ(reported_rpm(99.49), 99);
  // Saturated at +-32767, the range of the RPM Enable setpoints (L2019-L2020) [MODEL]: the
  // same magnitude both ways, never -32768.
  EXPECT_EQ(reported_rpm(1e6), 32767);
  EXPECT_EQ(reported_rpm(-1e6), -32767);
  EXPECT_EQ(reported_rpm(32766.4), 32766); // one inside
  EXPECT_EQ(reported_rpm(-32766.4), -32766);
  EXPECT_EQ(reported_rpm(32767.0), 32767); // at the limit
  EXPECT_EQ(reported_rpm(-32767.0), -32767);
  EXPECT_EQ(reported_rpm(32767.5), 32767); // rounds to one beyond
  EXPECT_EQ(reported_rpm(-32767.5), -32767);
  EXPECT_EQ(reported_rpm(-32768.0), -32767);
}

TEST(Ans1Speed, SpeedWordsSaturateSymmetricallyAt32767) {
  // Production rate S x M / D (L2536) goes through the same saturation as the speed.
  EXPECT_EQ(saturated_speed_word(-32766.0), -32766);
  EXPECT_EQ(saturated_speed_word(-32767.0), -32767);
  EXPECT_EQ(saturated_speed_word(-32768.0), -32767);
  EXPECT_EQ(saturated_speed_word(-40000.0), -32767); // -100 RPM x 400
  EXPECT_EQ(saturated_speed_word(32766.0), 32766);
  EXPECT_EQ(saturated_speed_word(32767.0), 32767);
  EXPECT_EQ(saturated_speed_word(32768.0), 32767);
  EXPECT_EQ(saturated_speed_word(40000.0), 32767);
}

TEST(Ans1Speed, TheWidestEnableWindowHoldsASaturatedSpeedEitherWay) {
  // RPM Enable Low/High -32767 .. 32767 (L2019-L2020) is the widest window a host can program:
  // a speed saturated in reverse is inside it as one saturated forward is.
  EXPECT_TRUE(speed_enabled(-32767, 32767, reported_rpm(-1e6)));
  EXPECT_TRUE(speed_enabled(-32767, 32767, reported_rpm(1e6)));
  // One step narrower at either end: the saturated speed on that side is outside.
  EXPECT_FALSE(speed_enabled(-32766, 32767, reported_rpm(-1e6)));
  EXPECT_FALSE(speed_enabled(-32767, 32766, reported_rpm(1e6)));
}

} // namespace
} // namespace hilrig::models::ans1
