// Plants in campaigns: the shipped ANS1 press-plant campaign stops when the physics says
// (numbers worked out by hand in the file's comments), a worn brake overruns the ANS1's
// limit exactly at the brake wear the physics predicts, a board output acts on the plant
// (the loop closes), and [plant] errors point at their key.

#include <array>
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

const std::string kPressFile = test::campaign_dir("ans1") + "/ans1_press_plant.toml";

// By hand (the file's comments): stop = d + r + (w0 - T r / 2J) J / T, d = 20 ms,
// r = 30 ms, w0 = 20 pi rad/s, J = 2 kg·m², T = s * 2000 N·m; = 35 ms + 62.83185 ms / s.
double predicted_stop_ms(double s) { return 35.0 + 20.0 * std::numbers::pi * 2.0 / (s * 2000.0) * 1e3; }

TEST(Ans1PressPlant, StopsWhenThePhysicsSaysAndTheWornBrakeIsCaught) {
  const Campaign c = load_campaign(kPressFile);
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
  EXPECT_EQ(r.totals.faults_caught, 1U);
  const rig::Measurement* nominal = test::find(r.runs[0], "stop.stop_time");
  ASSERT_NE(nominal, nullptr);
  // The standstill is located to the nanosecond: within 1e-6 ms of the closed form.
  EXPECT_NEAR(nominal->value, predicted_stop_ms(1.0), 1e-6);
  EXPECT_NEAR(nominal->value, 97.8318531, 1e-6);
  EXPECT_EQ(nominal->outcome, Outcome::Pass);
  const rig::Measurement* worn = test::find(r.runs[1], "stop.stop_time");
  ASSERT_NE(worn, nullptr);
  EXPECT_NEAR(worn->value, predicted_stop_ms(0.5), 1e-6);
  EXPECT_NEAR(worn->value, 160.6637061, 1e-6);
  EXPECT_EQ(worn->outcome, Outcome::Fail);
  // The board saw it too: its stop overrun output fired.
  const rig::Measurement* fired = test::find(r.runs[1], "stop.fault_output");
  ASSERT_NE(fired, nullptr);
  EXPECT_EQ(fired->value, 1.0);
}

// s* = 62.83185 / (150 - 35): a brake at s*(1 + e) stops within the 150 ms limit, one at
// s*(1 - e) overruns it, down to e = 1e-5 (a stop time 1.5 us from the limit).
TEST(Ans1PressPlant, AWornBrakeOverrunsAtTheWearThePhysicsPredicts) {
  const double s_star = 20.0 * std::numbers::pi * 2.0 / 2000.0 * 1e3 / (150.0 - 35.0);
  EXPECT_NEAR(s_star, 0.546364, 1e-6);
  const std::string text = test::read_file(kPressFile);
  const std::string nominal = "scale = 1.0";
  const std::size_t at = text.find(nominal);
  ASSERT_NE(at, std::string::npos);
  for (const double e : {-1e-3, -1e-4, -1e-5, 1e-5, 1e-4, 1e-3}) {
    std::string t = text;
    t.replace(at, nominal.size(), fmt::format("scale = {:.17g}", s_star * (1.0 + e)));
    const Campaign c = parse_campaign(t, "worn.toml");
    const RunOutput out = Executive(c).run(c.runs[0]);
    const rig::Measurement* m = test::find(out.result, "stop.stop_time");
    ASSERT_NE(m, nullptr) << e;
    EXPECT_NEAR(m->value, predicted_stop_ms(s_star * (1.0 + e)), 1e-6) << e;
    EXPECT_EQ(m->outcome, e > 0 ? Outcome::Pass : Outcome::Fail) << e << " " << m->value;
  }
}

// A sweep over a physical parameter: each point's stop time is the closed form's.
TEST(Ans1PressPlant, SweepsOverThePlantsParameters) {
  const std::string text = test::read_file(kPressFile) + R"(
[[sweep]]
key = "plant.brake_torque"
values = [2000.0, 1500.0, 1000.0]
)";
  const Campaign c = parse_campaign(text, "sweep.toml");
  ASSERT_EQ(c.points.size(), 3U);
  for (std::size_t p = 0; p < 3; ++p) {
    const RunOutput out = Executive(c).run(c.runs[p]);
    const rig::Measurement* m = test::find(out.result, "stop.stop_time");
    ASSERT_NE(m, nullptr);
    const double s = std::array{1.0, 0.75, 0.5}[p];
    EXPECT_NEAR(m->value, predicted_stop_ms(s), 1e-6) << p;
  }
}

// The loop closes: the reference PLS's output (on over counts [0, 200)) enables the motor of
// a rotary axis at rest; the shaft runs up at (T_m - T_c) / J, the board switches the motor
// off once it sees count 200, and Coulomb friction stops the shaft T_c / J later in
// proportion: stop time after the output falls = w_off J / T_c, w_off = a1 (t_off - t_on),
// with t_on and t_off the board's output edges in the trace.
TEST(PlantInTheLoop, TheBoardsOutputActsOnThePlant) {
  const std::string text = R"([campaign]
name = "loop"
end = "2s"
seed = 9
[dut]
model = "reference_pls"
[dut.params]
on = 0
off = 200
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "ls1"
board = "OUT"
[encoder]
lines = 100
[plant]
kind = "rotary_axis"
motor_inertia = 0.001
load_inertia = 0.01
motor_torque = 1.0
coulomb_torque = 0.3
start_motor = false
[plant.inputs]
motor_enable = "ls1"
[[check]]
kind = "brake_stop_time"
name = "coast"
brake_line = "ls1"
applied_level = "low"
limit_ms = 1000
)";
  const Campaign c = parse_campaign(text, "loop.toml");
  const RunOutput out = Executive(c).run(c.runs[0]);
  const std::vector<Edge> ls1 = out.trace->edges_of("ls1");
  ASSERT_EQ(ls1.size(), 2U);
  ASSERT_EQ(ls1[0].level, Level::High);
  ASSERT_EQ(ls1[1].level, Level::Low);
  const double j = 0.011;
  const double on = (ls1[1].time - ls1[0].time).seconds();
  const double w_off = (1.0 - 0.3) / j * on;
  const rig::Measurement* m = test::find(out.result, "coast.stop_time");
  ASSERT_NE(m, nullptr);
  EXPECT_NEAR(m->value, w_off * j / 0.3 * 1e3, 1e-6);
  // The motor went off once the board saw count 200 (its edge half a count before, at
  // 199.5 counts = 0.49875 turn), a scan and the output delay later (< 1 count at most).
  const double turned = 0.5 * (0.7 / j) * on * on / (2.0 * std::numbers::pi);
  EXPECT_GE(turned, 199.5 / 400.0);
  EXPECT_LT(turned, 201.0 / 400.0);

  // The board's output rules from time 0: a plant that would start with its motor on
  // follows the output's initial low level, so the run is the same.
  std::string motor_on = text;
  motor_on.replace(motor_on.find("start_motor = false"), std::string("start_motor = false").size(),
                   "start_motor = true");
  const Campaign c2 = parse_campaign(motor_on, "loop_on.toml");
  const RunOutput out2 = Executive(c2).run(c2.runs[0]);
  EXPECT_EQ(out2.trace->edges_of("ls1"), ls1);
  const rig::Measurement* m2 = test::find(out2.result, "coast.stop_time");
  ASSERT_NE(m2, nullptr);
  EXPECT_EQ(m2->value, m->value);
}

struct BadPlant {
  const char* line;   // a line of the shipped file
  const char* change; // what replaces it
  const char* key;
};

TEST(PlantReader, BadPlantParametersPointAtTheirKey) {
  const std::string text = test::read_file(kPressFile);
  for (const BadPlant& b :
       {BadPlant{"brake_torque = 2000.0", "brake_torque = -1.0", "plant.brake_torque"},
        BadPlant{"brake_torque = 2000.0", "brake_torque = nan", "plant.brake_torque"},
        BadPlant{"brake_torque = 2000.0", "brake_torque = 1e9", "plant.brake_torque"},
        BadPlant{"brake_torque = 2000.0", "brake_torke = 2000.0", "plant.brake_torke"},
        BadPlant{"rod_length = 0.3", "rod_length = 0.01", "plant.rod_length"},
        BadPlant{"valve_delay = 0.020", "valve_delay = 11.0", "plant.valve_delay"},
        BadPlant{"crank_inertia = 2.0", "crank_inertia = 0.0", "plant.crank_inertia"},
        BadPlant{"start_speed = 62.83185307179586", "start_speed = inf", "plant.start_speed"}}) {
    const std::size_t at = text.find(b.line);
    ASSERT_NE(at, std::string::npos) << b.line;
    const auto line_no = static_cast<std::size_t>(
                             std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) +
                         1;
    std::string t = text;
    t.replace(at, std::string(b.line).size(), b.change);
    try {
      (void)parse_campaign(t, "bad.toml");
      ADD_FAILURE() << b.change << " was accepted";
    } catch (const CampaignError& e) {
      EXPECT_EQ(e.key(), b.key) << b.change;
      EXPECT_EQ(e.where().line, line_no) << b.change << ": " << e.what();
    }
  }
}

TEST(PlantReader, InputsChangesAndMotionAreChecked) {
  const std::string text = test::read_file(kPressFile);
  const auto rejects = [&](const std::string& from, const std::string& to, const std::string& key) {
    std::string t = text;
    const std::size_t at = t.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    try {
      (void)parse_campaign(t, "bad.toml");
      ADD_FAILURE() << to << " was accepted";
    } catch (const CampaignError& e) {
      EXPECT_EQ(e.key(), key) << to << ": " << e.what();
      EXPECT_GT(e.where().line, 0U) << to;
    }
  };
  // The valve monitor drives a board input; stop_fault is a board output.
  rejects("valve_monitor = \"brake\"", "valve_monitor = \"stop_fault\"", "plant.valve_monitor");
  // A plant input is driven by a board output; "brake" is a board input.
  rejects("valve_monitor = \"brake\"", "[plant.inputs]\nvalve = \"brake\"", "plant.inputs.valve");
  rejects("param = \"brake_torque\"", "param = \"brake_wear\"", "plant.change[0].param");
  rejects("scale = 1.0", "scale = -0.5", "plant.change[0].scale");
  rejects("scale = 1.0", "scale = 1.0\nvalue = 5.0", "plant.change[0].value");
  rejects("input = \"valve\"", "input = \"clutch\"", "plant.command[0].input");
  rejects("kind = \"press\"", "kind = \"hydraulic\"", "plant.kind");
  rejects("[encoder]", "[motion]\n[[motion.move]]\nkind = \"dwell\"\nduration = \"1ms\"\n[encoder]", "plant");
  // A fault that scales the brake to a negative torque is caught at its value.
  rejects("\"plant.change[0].scale\" = 0.5", "\"plant.change[0].scale\" = -2.0",
          "fault[0].set: plant.change[0].scale");
}

} // namespace
} // namespace hilrig::campaign
