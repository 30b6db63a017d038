// Resolver -> R/D converter: the tracking property (within 1/4 count at 12 bits after
// settling, over speeds and seeds) and each resolver fault detected or visible.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "signals/motion_profile.hpp"
#include "signals/rd_converter.hpp"
#include "signals/resolver.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

constexpr double kQuarterCount = 0.25 / 4096.0; // in turns

double turn_error(double a, double b) {
  const double d = a - b;
  return d - std::round(d);
}

struct Rig {
  Resolver resolver;
  RdConverter rd;
  double rate_hz;
  Nanos t{0};
  std::size_t i = 0;
  // Runs until `until`, calling check() after each completed R/D window.
  template <class Check> void run(Nanos until, Check check) {
    while (t < until) {
      const std::size_t before = rd.updates();
      rd.feed(resolver.sample(t));
      if (rd.updates() != before) check();
      ++i;
      t = Nanos::from_seconds(static_cast<double>(i) / rate_hz);
    }
  }
  void run(Nanos until) {
    run(until, [] {});
  }
};

Rig make_rig(double hz, double tr, double phase, double rate_hz, AngleFunction angle) {
  ResolverParams rp;
  rp.excitation_hz = hz;
  rp.transformation_ratio = tr;
  rp.excitation_phase_rad = phase;
  RdParams dp;
  dp.excitation_hz = hz;
  dp.excitation_phase_rad = phase;
  dp.nominal_amplitude = tr;
  return Rig{Resolver(rp, std::move(angle)), RdConverter(dp), rate_hz};
}

class RdTracking : public ::testing::TestWithParam<double> {};

TEST_P(RdTracking, ConstantSpeedWithinAQuarterCountAfterSettling) {
  const double speed = GetParam(); // turns per second
  for (unsigned seed = 1; seed <= 4; ++seed) {
    std::mt19937 rng(seed * 977u + 13u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double hz = 2200.0 + u(rng) * 4800.0;
    const double tr = 0.9 + 0.1 * u(rng);
    const double phase = 2.0 * std::numbers::pi * u(rng);
    const double rate = 60'000.0 + u(rng) * 140'000.0;
    const double start = u(rng);
    const AngleFunction angle = angle_at_constant_speed(start, speed);
    Rig rig = make_rig(hz, tr, phase, rate, angle);
    rig.run(100_ms); // settling
    rig.rd.clear_faults();
    double worst = 0.0;
    std::size_t checks = 0;
    rig.run(200_ms, [&] {
      const Nanos at = rig.rd.last_update();
      worst = std::fmax(worst, std::fabs(turn_error(rig.rd.angle_turns(), angle(at))));
      ++checks;
    });
    SCOPED_TRACE(::testing::Message()
                 << "speed " << speed << " seed " << seed << " f " << hz << " rate " << rate);
    EXPECT_GT(checks, 200u); // at least 2.2 kHz for 100 ms
    EXPECT_LE(worst, kQuarterCount);
    EXPECT_FALSE(rig.rd.latched().any());
    EXPECT_NEAR(rig.rd.velocity_turns_per_s(), speed, 1e-3 + 1e-4 * std::fabs(speed));
  }
}

INSTANTIATE_TEST_SUITE_P(Speeds, RdTracking, ::testing::Values(-37.5, -3.3, 0.0, 0.7, 12.0, 50.0));

TEST(RdConverter, TracksAgainAfterAnAccelerationToCruise) {
  // From rest, 200 turns/s^2 for 100 ms to 20 turns/s, then cruise: the loop (not only
  // its acquisition) must pull the speed in and settle within a quarter count.
  MotionProfile p(0.3);
  p.accelerate(200.0, 100_ms).cruise(400_ms);
  const AngleFunction angle = angle_from_profile(p, 1.0);
  Rig rig = make_rig(3000.0, 0.95, 1.0, 90'000.0, angle);
  rig.run(350_ms);
  double worst = 0.0;
  rig.run(500_ms, [&] {
    worst = std::fmax(worst, std::fabs(turn_error(rig.rd.angle_turns(), angle(rig.rd.last_update()))));
  });
  EXPECT_LE(worst, kQuarterCount);
  EXPECT_NEAR(rig.rd.velocity_turns_per_s(), 20.0, 1e-3);
}

TEST(RdConverter, CountsAtTwelveBits) {
  // Static angle at the centre of count 1000: (1000.5)/4096 turn -> counts() = 1000.
  Rig rig = make_rig(5000.0, 1.0, 0.0, 100'000.0, angle_at_constant_speed(1000.5 / 4096.0, 0.0));
  rig.run(50_ms);
  EXPECT_EQ(rig.rd.counts(), 1000u);
  EXPECT_TRUE(rig.rd.tracking());
}

TEST(RdConverter, RejectsExcitationOutsideRange) {
  RdParams p;
  p.excitation_hz = 8000.0;
  EXPECT_THROW(RdConverter{p}, std::invalid_argument);
}

// Static shaft at `turns`, healthy for 50 ms, then `fault` for 20 ms.
Rig faulted(double turns, const ResolverFaults& fault) {
  Rig rig = make_rig(5000.0, 1.0, 0.0, 100'000.0, angle_at_constant_speed(turns, 0.0));
  rig.run(50_ms);
  EXPECT_FALSE(rig.rd.latched().any());
  EXPECT_LE(std::fabs(turn_error(rig.rd.angle_turns(), turns)), kQuarterCount);
  rig.resolver.set_faults(fault);
  rig.run(70_ms);
  return rig;
}

TEST(RdFaults, OpenSinCoilIsLossOfSignal) {
  // At 0.3 turn only |cos 108 deg| = 0.309 of the amplitude is left: below half (LOS).
  ResolverFaults f;
  f.sin_open = true;
  const Rig rig = faulted(0.3, f);
  EXPECT_TRUE(rig.rd.status().loss_of_signal);
  EXPECT_TRUE(rig.rd.status().degradation);
}

TEST(RdFaults, OpenCosCoilDegradesAndMovesTheAngle) {
  // At 1/8 turn the sin winding alone gives amplitude sqrt(0.5) = 0.707 (< 0.85: degradation)
  // and the converter settles on atan2(0.707, 0) = 90 deg = 0.25 turn: 512 counts off.
  ResolverFaults f;
  f.cos_open = true;
  const Rig rig = faulted(0.125, f);
  EXPECT_TRUE(rig.rd.status().degradation);
  EXPECT_FALSE(rig.rd.status().loss_of_signal);
  EXPECT_NEAR(rig.rd.angle_turns(), 0.25, kQuarterCount);
}

TEST(RdFaults, AmplitudeImbalanceMovesTheAngle) {
  // sin gain 1.1 at 45 deg: atan(1.1) = 47.726 deg = 0.132573 turn, 31 counts above 512.
  // The amplitude sqrt((1.21 + 1)/2) = 1.051 stays inside the window; the sudden 31-count
  // step exceeds the 16-count loss-of-tracking threshold for a moment.
  ResolverFaults f;
  f.sin_gain = 1.1;
  const Rig rig = faulted(0.125, f);
  EXPECT_NEAR(rig.rd.angle_turns(), std::atan(1.1) / (2.0 * std::numbers::pi), kQuarterCount);
  EXPECT_NEAR(rig.rd.angle_turns() * 4096.0 - 512.0, 31.0, 0.1);
  EXPECT_FALSE(rig.rd.latched().loss_of_signal);
  EXPECT_FALSE(rig.rd.latched().degradation);
  EXPECT_TRUE(rig.rd.latched().loss_of_tracking);
  EXPECT_FALSE(rig.rd.status().loss_of_tracking); // settled on the new angle
}

TEST(RdFaults, LargeImbalanceOnARotatingShaftIsDegradation) {
  // sin gain 1.3: at 90 deg the amplitude is 1.3 > 1.15.
  Rig rig = make_rig(4000.0, 1.0, 0.0, 100'000.0, angle_at_constant_speed(0.0, 5.0));
  rig.run(50_ms);
  EXPECT_FALSE(rig.rd.latched().any());
  ResolverFaults f;
  f.sin_gain = 1.3;
  rig.resolver.set_faults(f);
  rig.run(300_ms);
  EXPECT_TRUE(rig.rd.latched().degradation);
}

TEST(RdFaults, CarrierPhaseShiftOnBothWindingsIsDegradation) {
  // Both windings 45 deg behind the reference: the synchronous demodulator sees cos 45 = 0.707
  // of the amplitude (< 0.85), but sin and cos shrink alike, so the angle stays.
  ResolverFaults f;
  f.sin_phase_rad = f.cos_phase_rad = std::numbers::pi / 4.0;
  const Rig rig = faulted(0.3, f);
  EXPECT_TRUE(rig.rd.status().degradation);
  EXPECT_NEAR(rig.rd.amplitude(), std::sqrt(0.5), 1e-3);
  EXPECT_LE(std::fabs(turn_error(rig.rd.angle_turns(), 0.3)), kQuarterCount);
}

TEST(RdFaults, CarrierPhaseShiftOnOneWindingMovesTheAngle) {
  // sin winding 30 deg shifted: demodulated sin shrinks by cos 30 = 0.866; at 45 deg the
  // angle becomes atan(0.866) = 40.89 deg = 0.113583 turn, 46.8 counts below 512.
  ResolverFaults f;
  f.sin_phase_rad = std::numbers::pi / 6.0;
  const Rig rig = faulted(0.125, f);
  const double expected = std::atan(std::cos(std::numbers::pi / 6.0)) / (2.0 * std::numbers::pi);
  EXPECT_NEAR(rig.rd.angle_turns(), expected, kQuarterCount);
  EXPECT_NEAR(rig.rd.angle_turns() * 4096.0 - 512.0, -46.8, 0.1);
}

TEST(RdFaults, ExcitationLossIsLossOfSignal) {
  ResolverFaults f;
  f.excitation_lost = true;
  const Rig rig = faulted(0.6, f);
  EXPECT_TRUE(rig.rd.status().loss_of_signal);
  EXPECT_NEAR(rig.rd.amplitude(), 0.0, 1e-12);
}

TEST(RdFaults, RecoveryAfterTheFaultClears) {
  ResolverFaults f;
  f.excitation_lost = true;
  Rig rig = faulted(0.6, f);
  rig.resolver.set_faults({});
  rig.run(120_ms);
  EXPECT_FALSE(rig.rd.status().any());
  EXPECT_LE(std::fabs(turn_error(rig.rd.angle_turns(), 0.6)), kQuarterCount);
}

} // namespace
} // namespace hilrig::signals
