// The Series 2700 as a press's top-stop cam (campaigns/pls2700/pls2700_press_plant.toml): a
// press plant turns the resolver, the 2700's output 1 drives the clutch/brake valve. The
// verdicts, stop times and stop positions are the ones worked out by hand in the file's
// comments; a brake worn just past each threshold the physics predicts flips its check.

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

const std::string kFile = test::campaign_dir("pls2700") + "/pls2700_press_plant.toml";

// By hand (the file's comments): the crank runs at w1 = J_f w_f0 / (J_f + J_c) = 10 pi rad/s
// when output 1 drops the valve at 2048 counts; brake T = s * 2000 N·m on J_c = 2 kg·m²,
// valve delay d = 20 ms, rise r = 30 ms.
constexpr double kW1 = 10.0 * std::numbers::pi;
constexpr double kJc = 2.0, kD = 0.020, kR = 0.030;

double stop_ms(double s) { return (kD + kR / 2.0 + kW1 * kJc / (s * 2000.0)) * 1e3; }

// Counts (4096 a turn) the crank turns from the valve's edge to rest.
double overtravel_counts(double s) {
  const double t = s * 2000.0;
  const double w2 = kW1 - t * kR / (2.0 * kJc);
  const double rad = kW1 * kD + kW1 * kR - t * kR * kR / (6.0 * kJc) + w2 * w2 * kJc / (2.0 * t);
  return rad * 4096.0 / (2.0 * std::numbers::pi);
}

// The 2700 drops its output at most one 200 us update after its latest excitation-peak
// sample (<= 200 us old) reached 2048: at 20,480 counts/s, <= 8.2 counts late (L377).
constexpr double kLagCounts = 9.0;

std::string with_wear(double s) {
  std::string t = test::read_file(kFile);
  const std::string nominal = "scale = 1.0";
  const std::size_t at = t.find(nominal);
  EXPECT_NE(at, std::string::npos);
  t.replace(at, nominal.size(), fmt::format("scale = {:.17g}", s));
  return t;
}

TEST(Pls2700PressPlant, StopsWhereThePhysicsSaysAndTheWornBrakeIsCaught) {
  EXPECT_NEAR(stop_ms(1.0), 66.4159265, 1e-6);
  EXPECT_NEAR(overtravel_counts(1.0), 1014.05, 0.01);
  EXPECT_NEAR(overtravel_counts(0.5), 1347.98, 0.01);
  const Campaign c = load_campaign(kFile);
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
  EXPECT_EQ(r.totals.faults_caught, 1U);
  for (std::size_t i = 0; i < 2; ++i) {
    const double s = i == 0 ? 1.0 : 0.5;
    const rig::Measurement* stop = test::find(r.runs[i], "stop.stop_time");
    ASSERT_NE(stop, nullptr);
    // The rig times the plant's located standstill from the board's edge: to the nanosecond.
    EXPECT_NEAR(stop->value, stop_ms(s), 1e-6) << s;
    EXPECT_EQ(stop->outcome, i == 0 ? Outcome::Pass : Outcome::Fail);
    // The board read the stopped crank through the plant's resolver: 2048 + overtravel,
    // floored, plus its output lag.
    const rig::Measurement* pos = test::find(r.runs[i], "stop_position");
    ASSERT_NE(pos, nullptr);
    EXPECT_GE(pos->value, std::floor(2048.0 + overtravel_counts(s))) << s;
    EXPECT_LE(pos->value, std::floor(2048.0 + overtravel_counts(s) + kLagCounts)) << s;
    EXPECT_EQ(pos->outcome, i == 0 ? Outcome::Pass : Outcome::Fail);
  }
}

// Stop time 90 ms at s* = w1 J_c / 2000 / (90 ms - 35 ms) = 0.571199: a brake a hair stronger
// stops in time, one a hair weaker does not.
TEST(Pls2700PressPlant, TheStopTimeLimitFallsAtTheWearThePhysicsPredicts) {
  const double s_star = kW1 * kJc / 2000.0 / (0.090 - 0.035);
  EXPECT_NEAR(s_star, 0.571199, 1e-6);
  for (const double e : {-1e-3, -1e-4, 1e-4, 1e-3}) {
    const Campaign c = parse_campaign(with_wear(s_star * (1.0 + e)), "worn.toml");
    const RunOutput out = Executive(c).run(c.runs[0]);
    const rig::Measurement* m = test::find(out.result, "stop.stop_time");
    ASSERT_NE(m, nullptr) << e;
    EXPECT_NEAR(m->value, stop_ms(s_star * (1.0 + e)), 1e-6) << e;
    EXPECT_EQ(m->outcome, e > 0 ? Outcome::Pass : Outcome::Fail) << e << " " << m->value;
  }
}

// Stop position 3328 is reached between s = 0.5577 (no lag) and 0.5663 (9 counts of lag):
// below that band the board reads the crank past 3328, above it short of it.
TEST(Pls2700PressPlant, TheStopPositionLimitFallsAtTheWearThePhysicsPredicts) {
  for (const double s : {0.54, 0.55, 0.57, 0.58}) {
    const bool over = 2048.0 + overtravel_counts(s) > 3328.0;
    const bool under = 2048.0 + overtravel_counts(s) + kLagCounts < 3328.0;
    ASSERT_TRUE(over || under) << s << ": inside the band the lag leaves open";
    const Campaign c = parse_campaign(with_wear(s), "worn.toml");
    const RunOutput out = Executive(c).run(c.runs[0]);
    const rig::Measurement* m = test::find(out.result, "stop_position");
    ASSERT_NE(m, nullptr) << s;
    EXPECT_EQ(m->outcome, under ? Outcome::Pass : Outcome::Fail) << s << " " << m->value;
  }
}

// start_flywheel_speed is checked like every plant key: finite, within ±1e4 rad/s, press only.
TEST(Pls2700PressPlant, AFlywheelStartSpeedOutOfRangePointsAtItsKey) {
  const std::string text = test::read_file(kFile);
  const std::string key = "start_flywheel_speed = 34.55751918948773";
  for (const char* bad : {"start_flywheel_speed = inf", "start_flywheel_speed = 1e5"}) {
    std::string t = text;
    const std::size_t at = t.find(key);
    ASSERT_NE(at, std::string::npos);
    t.replace(at, key.size(), bad);
    try {
      (void)parse_campaign(t, "bad.toml");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const CampaignError& e) {
      EXPECT_EQ(e.key(), "plant.start_flywheel_speed") << bad;
    }
  }
}

} // namespace
} // namespace hilrig::campaign
