// Profile formulas (spec §3.2, §3.3): move duration and peak speed of trapezoid and triangle
// moves, and the S-curve ramp-time factors M-08 and M-09. Common assumptions of the
// examples: v_s = 100 steps/s, A = D = 10 steps/ms/s = 10,000 steps/s² (M-07).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "models/smd23e/kinematics.hpp"

namespace hilrig::models::smd23e {
namespace {

constexpr double kVs = 100.0;
constexpr double kA = 10.0 * 1000.0; // M-07: programmed 10 steps/ms/s = 10,000 steps/s²
const RampShape kLinear{1.0};

TEST(Smd23eKinematics, M07HandyRampsFromTheExamples) {
  // 100 → 1100: 60 steps, 0.1 s; 100 → 2100: 220 steps, 0.2 s; 100 → 3100: 480 steps, 0.3 s.
  EXPECT_DOUBLE_EQ(ramp_steps(kVs, 1100, kA, kLinear), 60.0);
  EXPECT_DOUBLE_EQ(ramp_time(kVs, 1100, kA, kLinear), 0.1);
  EXPECT_DOUBLE_EQ(ramp_steps(kVs, 2100, kA, kLinear), 220.0);
  EXPECT_DOUBLE_EQ(ramp_time(kVs, 2100, kA, kLinear), 0.2);
  EXPECT_DOUBLE_EQ(ramp_steps(kVs, 3100, kA, kLinear), 480.0);
  EXPECT_DOUBLE_EQ(ramp_time(kVs, 3100, kA, kLinear), 0.3);
}

TEST(Smd23eKinematics, TrapezoidDurationAndPeak) {
  // N = 1000, v_p = 1100: 60 + 880 + 60 steps; 0.1 + 880/1100 + 0.1 = 1.0 s.
  const ProfileFigures f = profile_figures(1000, kVs, 1100, kA, kA, kLinear);
  EXPECT_FALSE(f.triangle);
  EXPECT_DOUBLE_EQ(f.peak_speed, 1100.0);
  EXPECT_NEAR(f.duration, 1.0, 1e-12);
}

TEST(Smd23eKinematics, TriangleDurationAndPeak) {
  // N = 100, v_p = 5000: 2·n_ramp(5000) ≫ 100, so a triangle;
  // v_peak = √(100² + 2·100·10⁴·10⁴/(2·10⁴)) = √1,010,000; T = (v_peak − 100)·2/10⁴.
  const ProfileFigures f = profile_figures(100, kVs, 5000, kA, kA, kLinear);
  EXPECT_TRUE(f.triangle);
  EXPECT_NEAR(f.peak_speed, std::sqrt(1'010'000.0), 1e-9);
  EXPECT_NEAR(f.duration, (std::sqrt(1'010'000.0) - 100.0) * 2.0 / kA, 1e-12);
  EXPECT_NEAR(f.accel_steps, 50.0, 1e-9); // equal rates: the peak is halfway
}

TEST(Smd23eKinematics, UnequalRatesPutThePeakLater) {
  // a = 20,000, d = 10,000, N = 300, v_p high: v_pk² = 100² + 2·300·a·d/(a+d) = 10⁴ + 4·10⁶.
  const ProfileFigures f = profile_figures(300, kVs, 1e6, 2 * kA, kA, kLinear);
  EXPECT_NEAR(f.peak_speed, std::sqrt(4'010'000.0), 1e-9);
  EXPECT_NEAR(f.accel_steps, (4'010'000.0 - 10'000.0) / (2 * 2 * kA), 1e-9); // 100 steps
  EXPECT_NEAR(f.decel_steps, 200.0, 1e-9);
}

TEST(Smd23eKinematics, StartingSpeedEqualToProgrammedSpeedHasNoRamps) {
  const ProfileFigures f = profile_figures(500, 1000, 1000, kA, kA, kLinear);
  EXPECT_NEAR(f.duration, 0.5, 1e-12); // T = N / v_s
}

TEST(Smd23eKinematics, M08TriangularSCurveDoublesTheRampTime) {
  const double linear = ramp_time(kVs, 1100, kA, RampShape{1.0});
  EXPECT_DOUBLE_EQ(ramp_time(kVs, 1100, kA, RampShape{0.0}), 2.0 * linear);
  // The S-ramp is point-symmetric: steps = mean speed × time = 600 × 0.2 = 120.
  EXPECT_DOUBLE_EQ(ramp_steps(kVs, 1100, kA, RampShape{0.0}), 120.0);
}

TEST(Smd23eKinematics, M09TrapezoidalSCurveWithHalfLinearIsOneThirdLonger) {
  const double linear = ramp_time(kVs, 1100, kA, RampShape{1.0});
  EXPECT_NEAR(ramp_time(kVs, 1100, kA, RampShape{0.5}) / linear, 4.0 / 3.0, 1e-12);
}

TEST(Smd23eKinematics, SCurvePiecesReachTheTargetSpeedAndDistance) {
  // The jerk pieces must integrate to exactly the closed-form ramp.
  for (const double f : {0.0, 0.25, 0.5, 0.75}) {
    std::vector<Piece> pieces;
    append_ramp(pieces, kVs, 1100, kA, RampShape{f});
    double t = 0;
    double p = 0;
    for (const Piece& pc : pieces) {
      t += pc.duration;
      p += pc.distance_at(pc.duration);
    }
    EXPECT_NEAR(pieces.back().velocity_at(pieces.back().duration), 1100.0, 1e-9) << f;
    EXPECT_NEAR(t, ramp_time(kVs, 1100, kA, RampShape{f}), 1e-12) << f;
    EXPECT_NEAR(p, ramp_steps(kVs, 1100, kA, RampShape{f}), 1e-9) << f;
    EXPECT_NEAR(pieces.front().a0, 0.0, 1e-12) << f; // smooth start: no acceleration step
  }
}

TEST(Smd23eKinematics, PlannedMovesCoverExactlyTheirStepsInTheirDuration) {
  // Property: for random moves the planned pieces end at N, at the formula's duration.
  std::mt19937 rng(23); // fixed seed
  std::uniform_int_distribution<int> steps(1, 200'000);
  std::uniform_int_distribution<int> speed(100, 300'000);
  std::uniform_int_distribution<int> rate(1, 5000);
  std::uniform_int_distribution<int> jerk(0, 2);
  for (int i = 0; i < 2000; ++i) {
    const double n = steps(rng);
    const double vp = speed(rng);
    const double a = 1000.0 * rate(rng);
    const double d = 1000.0 * rate(rng);
    const RampShape shape{jerk(rng) == 0 ? 1.0 : (jerk(rng) == 1 ? 0.0 : 0.5)};
    const Motion m(Nanos{0}, plan_move(n, kVs, vp, a, d, shape));
    const ProfileFigures f = profile_figures(n, kVs, vp, a, d, shape);
    ASSERT_NEAR(m.total_steps(), n, 1e-6 * n);
    ASSERT_LE(std::abs(m.end().count() - Nanos::from_seconds(f.duration).count()), 1);
    // Speed never exceeds the peak and never drops under v_s.
    const Nanos mid = Nanos{m.end().count() / 2};
    ASSERT_LE(m.velocity(mid), f.peak_speed * (1 + 1e-9));
    ASSERT_GE(m.velocity(mid), kVs * (1 - 1e-9));
  }
}

TEST(Smd23eKinematics, TimeAtProgressInvertsProgress) {
  const Motion m(Nanos{1000}, plan_move(1000, kVs, 1100, kA, kA, kLinear));
  for (int k = 1; k <= 1000; k += 37) {
    const Nanos t = m.time_at_progress(k);
    EXPECT_GE(m.progress(t), k);
    EXPECT_LT(m.progress(t - Nanos{1}), k);
  }
  // Step 60 is the end of the ramp: 0.1 s after the start.
  EXPECT_LE(std::abs(m.time_at_progress(60).count() - (1000 + 100'000'000)), 2);
}

} // namespace
} // namespace hilrig::models::smd23e
