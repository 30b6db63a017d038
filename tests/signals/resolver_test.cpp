// Resolver stator synthesis: V_sin = TR * Vref * sin(theta), V_cos = TR * Vref * cos(theta),
// carrier in phase with the reference (ans1.md §2.1, pls2700.md §2.4); values by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "signals/motion_profile.hpp"
#include "signals/resolver.hpp"
#include "signals/stator_band.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

ResolverParams params(double hz = 5000.0, double amplitude = 2.0, double tr = 0.5) {
  ResolverParams p;
  p.excitation_hz = hz;
  p.excitation_amplitude = amplitude;
  p.transformation_ratio = tr;
  return p;
}

TEST(Resolver, AcceptsOnlyTheAns1ExcitationRange) {
  // L1455: 2.2 kHz to 7 kHz.
  const AngleFunction still = angle_at_constant_speed(0.0, 0.0);
  EXPECT_NO_THROW(Resolver(params(2200.0), still));
  EXPECT_NO_THROW(Resolver(params(7000.0), still));
  EXPECT_THROW(Resolver(params(2199.0), still), std::invalid_argument);
  EXPECT_THROW(Resolver(params(7001.0), still), std::invalid_argument);
  EXPECT_THROW(Resolver(params(5000.0, 1.0, 0.0), still), std::invalid_argument); // TR 0
  EXPECT_THROW(Resolver(params(), AngleFunction{}), std::invalid_argument);
}

TEST(Resolver, SamplesAtThirtyDegreesByHand) {
  // 5 kHz, Vref peak 2 V, TR 0.5, theta = 1/12 turn = 30 deg. At t = 50 us the carrier is
  // at 2*pi*5000*50e-6 = pi/2, so Vref = 2; V_sin = 0.5*2*sin 30 = 0.5, V_cos = 0.5*2*cos 30.
  const Resolver r(params(), angle_at_constant_speed(1.0 / 12.0, 0.0));
  const ResolverSample s = r.sample(50_us);
  EXPECT_NEAR(s.reference, 2.0, 1e-12);
  EXPECT_NEAR(s.sin, 0.5, 1e-12);
  EXPECT_NEAR(s.cos, std::sqrt(3.0) / 2.0, 1e-12);
  // At t = 0 and t = 100 us (half a period) the carrier crosses zero: both windings 0.
  EXPECT_NEAR(r.sample(0_ns).sin, 0.0, 1e-12);
  EXPECT_NEAR(r.sample(100_us).cos, 0.0, 1e-12);
  // At 150 us the carrier is at its negative peak: the windings follow in phase.
  EXPECT_NEAR(r.sample(150_us).sin, -0.5, 1e-12);
}

TEST(Resolver, EnvelopesFollowTheTrajectory) {
  // 2 turns/s from 0: at 125 ms theta = 0.25 turn -> sin envelope TR, cos envelope 0.
  const Resolver r(params(), angle_at_constant_speed(0.0, 2.0));
  const ResolverEnvelope e = r.envelope(125_ms);
  EXPECT_NEAR(e.sin, 0.5, 1e-12);
  EXPECT_NEAR(e.cos, 0.0, 1e-12);
  EXPECT_NEAR(r.angle_turns(125_ms), 0.25, 1e-12);
}

TEST(Resolver, AngleFromAMotionProfileInCounts) {
  // 4096 counts/s^2 from rest: at 0.5 s the position is 4096*0.25/2 = 512 counts = 1/8 turn.
  MotionProfile p(0.0);
  p.accelerate(4096.0, 1_s);
  const Resolver r(params(5000.0, 1.0, 1.0), angle_from_profile(p, 4096.0));
  EXPECT_NEAR(r.angle_turns(500_ms), 0.125, 1e-12);
  EXPECT_NEAR(r.envelope(500_ms).sin, std::sqrt(0.5), 1e-12);
}

TEST(Resolver, SampleBlockUsesTheRate) {
  const Resolver r(params(), angle_at_constant_speed(0.1, 3.0));
  const auto block = r.sample_block(1_ms, 100'000.0, 5);
  ASSERT_EQ(block.size(), 5u);
  for (std::size_t i = 0; i < block.size(); ++i) {
    EXPECT_EQ(block[i].time, 1_ms + 10_us * static_cast<std::int64_t>(i));
    EXPECT_DOUBLE_EQ(block[i].sin, r.sample(block[i].time).sin);
  }
}

TEST(Resolver, WaveformsCarryTheSignalsAndLaterFaults) {
  Resolver r(params(), angle_at_constant_speed(1.0 / 12.0, 0.0));
  const Waveform vsin = r.sin_waveform();
  const Waveform vcos = r.cos_waveform();
  const Waveform vref = r.reference_waveform();
  EXPECT_NEAR(vref(50_us), 2.0, 1e-12);
  EXPECT_NEAR(vsin(50_us), 0.5, 1e-12);
  EXPECT_NEAR(vcos(50_us), std::sqrt(3.0) / 2.0, 1e-12);
  ResolverFaults f;
  f.sin_open = true;
  r.set_faults(f);
  EXPECT_EQ(vsin(50_us), 0.0);
  EXPECT_NEAR(vcos(50_us), std::sqrt(3.0) / 2.0, 1e-12);
}

TEST(Resolver, FaultsActOnTheWindings) {
  Resolver r(params(), angle_at_constant_speed(1.0 / 12.0, 0.0));
  ResolverFaults f;
  f.excitation_lost = true;
  r.set_faults(f);
  EXPECT_EQ(r.sample(50_us).sin, 0.0);
  EXPECT_EQ(r.sample(50_us).cos, 0.0);
  EXPECT_NEAR(r.sample(50_us).reference, 2.0, 1e-12); // the board's reference is still there
  f = ResolverFaults{};
  f.sin_gain = 1.2; // imbalance: 0.5 * 1.2 = 0.6
  r.set_faults(f);
  EXPECT_NEAR(r.sample(50_us).sin, 0.6, 1e-12);
  f = ResolverFaults{};
  // Carrier shifted a quarter period: at 50 us sin(pi/2 + pi/2) = 0.
  f.cos_phase_rad = std::numbers::pi / 2.0;
  r.set_faults(f);
  EXPECT_NEAR(r.sample(50_us).cos, 0.0, 1e-12);
  EXPECT_NEAR(r.sample(100_us).cos, -std::sqrt(3.0) / 2.0, 1e-12); // sin(pi + pi/2) = -1
}

// The stator fault band both resolver boards judge by (ANS1 resolver_min/max_ratio 0.75 / 1.25
// [MODEL], models/ans1/README.md; Series 2700 min/max_stator_ratio, models/pls2700/README.md
// "Decoder"): closed, and a ratio within a relative 1e-9 of a limit counts as at the limit.
TEST(StatorBand, IsClosedWithARelativeSlackOfOneBillionth) {
  for (const double lo : {0.75, 0.5}) {
    const double hi = lo == 0.75 ? 1.25 : 1.5;
    EXPECT_TRUE(stator_ratio_in_band(lo, lo, hi));                  // at the lower limit
    EXPECT_TRUE(stator_ratio_in_band(hi, lo, hi));                  // at the upper limit
    EXPECT_TRUE(stator_ratio_in_band(lo * (1.0 - 0.5e-9), lo, hi)); // rounding below it
    EXPECT_TRUE(stator_ratio_in_band(hi * (1.0 + 0.5e-9), lo, hi)); // rounding above it
    EXPECT_FALSE(stator_ratio_in_band(lo * (1.0 - 2e-9), lo, hi));  // beyond the slack
    EXPECT_FALSE(stator_ratio_in_band(hi * (1.0 + 2e-9), lo, hi));
    EXPECT_TRUE(stator_ratio_in_band(lo * 1.001, lo, hi)); // one step inside each limit
    EXPECT_TRUE(stator_ratio_in_band(hi * 0.999, lo, hi));
    EXPECT_FALSE(stator_ratio_in_band(lo * 0.999, lo, hi)); // one step beyond each limit
    EXPECT_FALSE(stator_ratio_in_band(hi * 1.001, lo, hi));
  }
}

} // namespace
} // namespace hilrig::signals
