// Detection power where a press plant brakes the shaft: the knob is a factor s on every brake
// torque the campaign gives (the nominal and each [[plant.change]], which re-states the torque
// at 0 ms in both campaigns), down; the threshold is where the plant's closed form puts the
// stop at the limit.

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/power/power.hpp"

namespace hilrig::power {
namespace {

PowerRow stop_row(const std::string& file) {
  const campaign::Campaign c = campaign::load_campaign(std::string(HILRIG_SOURCE_DIR) + "/campaigns/" + file);
  PowerOptions options;
  options.checks = {"stop"};
  const PowerResult r = measure_power(c, options);
  EXPECT_EQ(r.rows.size(), 1u);
  return r.rows.empty() ? PowerRow{} : r.rows[0];
}

// ans1_press_plant.toml, by hand in its comments (SI, no ram mass, no friction): valve delay
// d = 20 ms, brake rise r = 30 ms, w0 = 20 pi rad/s on J_c = 2 kg·m²; a brake of torque T stops
// d + r/2 + w0 J_c / T after the valve drops; with T = s x 2000 N·m: 35 ms + 20 pi / s ms.
// The Stop Time Limit 150 ms (CB8 w5, ans1 manual seeds/000_08a2edf5547d4d1e.txt:2108) is
// reached at s* = 20 pi / 115 = 0.546364: a weaker brake overruns it.
TEST(PowerPlant, Ans1PressPlantThresholdIsTheBrakeTorqueThatStopsAtTheLimit) {
  const double t_star = 20.0 * std::numbers::pi / 115.0;
  EXPECT_NEAR(t_star, 0.5463639, 1e-7);
  const PowerRow row = stop_row("ans1/ans1_press_plant.toml");
  EXPECT_EQ(row.knob, "plant brake_torque factor");
  EXPECT_EQ(row.direction, "down");
  ASSERT_TRUE(row.nominal && row.threshold && row.last_pass && row.measured && row.limit) << row.reason;
  EXPECT_DOUBLE_EQ(*row.nominal, 1.0);
  EXPECT_LT(*row.threshold, t_star);
  EXPECT_GT(*row.threshold, t_star - 2e-6); // bisected to 1e-6
  EXPECT_GE(*row.last_pass, t_star - 1e-9);
  EXPECT_EQ(row.measurement, "stop.stop_time");
  EXPECT_DOUBLE_EQ(*row.limit, 150.0);
  EXPECT_GT(*row.measured, 150.0);
  EXPECT_LE(*row.measured, 150.001);
}

// pls2700_press_plant.toml, by hand in its comments: the crank locked to the flywheel at
// w1 = 10 pi rad/s; from the output's edge the stop takes 35 ms + w1 J_c / T = 35 ms + 20 pi / T s;
// with T = s x 2000 N·m: 35 ms + 10 pi / s ms; the check's 90 ms limit is reached at
// s* = 10 pi / 55 = 0.571199.
TEST(PowerPlant, Pls2700PressPlantThresholdIsTheBrakeTorqueThatStopsAtTheLimit) {
  const double t_star = 10.0 * std::numbers::pi / 55.0;
  EXPECT_NEAR(t_star, 0.5711987, 1e-7);
  const PowerRow row = stop_row("pls2700/pls2700_press_plant.toml");
  EXPECT_EQ(row.knob, "plant brake_torque factor");
  ASSERT_TRUE(row.nominal && row.threshold && row.last_pass && row.measured && row.limit) << row.reason;
  EXPECT_DOUBLE_EQ(*row.nominal, 1.0);
  EXPECT_LT(*row.threshold, t_star);
  EXPECT_GT(*row.threshold, t_star - 2e-6);
  EXPECT_GE(*row.last_pass, t_star - 1e-9);
  EXPECT_DOUBLE_EQ(*row.limit, 90.0);
  EXPECT_GT(*row.measured, 90.0);
  EXPECT_LE(*row.measured, 90.001);
}

// Across each threshold, probed directly (not through the bisection): a brake a hair weaker
// than s* overruns the limit, one a hair stronger stops within it, and the campaign's own
// nominal brake (s = 1) and its worn-brake fault's 0.5 fall on their sides. The change at
// 0 ms re-states the torque: the knob scales it too, or s would never reach the plant.
TEST(PowerPlant, ProbesAcrossTheBrakeThresholdFailBelowAndPassAbove) {
  struct Case {
    std::string file;
    double s_star;
  };
  for (const Case& k : {Case{"ans1/ans1_press_plant.toml", 20.0 * std::numbers::pi / 115.0},
                        Case{"pls2700/pls2700_press_plant.toml", 10.0 * std::numbers::pi / 55.0}}) {
    const campaign::Campaign c =
        campaign::load_campaign(std::string(HILRIG_SOURCE_DIR) + "/campaigns/" + k.file);
    for (const double rel : {1e-5, 1e-4, 1e-2}) {
      EXPECT_EQ(probe_plant_brake_factor(c, "stop", k.s_star * (1.0 - rel), c.seed), Probe::Fail)
          << k.file << rel;
      EXPECT_EQ(probe_plant_brake_factor(c, "stop", k.s_star * (1.0 + rel), c.seed), Probe::Pass)
          << k.file << rel;
    }
    EXPECT_EQ(probe_plant_brake_factor(c, "stop", 1.0, c.seed), Probe::Pass) << k.file;
    EXPECT_EQ(probe_plant_brake_factor(c, "stop", 0.5, c.seed), Probe::Fail) << k.file;
  }
}

} // namespace
} // namespace hilrig::power
