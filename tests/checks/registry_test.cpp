#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "check_test_support.hpp"
#include "rig/checks/registry.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using nlohmann::json;
using test::find;

TEST(Registry, NamesEveryCheckKindTheCampaignsUse) {
  std::set<std::string> names;
  for (const auto& k : check_kinds()) {
    names.insert(k.name);
    EXPECT_TRUE(k.run) << k.name;
    EXPECT_FALSE(k.summary.empty()) << k.name;
  }
  EXPECT_EQ(names, (std::set<std::string>{"throughput", "debounce", "advance_counts", "brake_stop_time",
                                          "edge_at_position", "pulse_width", "word_equals", "word_within",
                                          "frame_decodes", "shaft_move", "word_bits"}));
  ASSERT_NE(find_check_kind("debounce"), nullptr);
  EXPECT_TRUE(find_check_kind("debounce")->needs_bisection);
  EXPECT_EQ(find_check_kind("nonsense"), nullptr);
}

TEST(Registry, ValidationNamesEveryProblem) {
  const CheckKind& k = *find_check_kind("throughput");
  EXPECT_TRUE(validate_check_params(k, json{{"output", "ls1"}, {"limit_us", 20}, {"setpoint", 100}}).empty());
  const auto errors = validate_check_params(k, json{{"output", 3}, {"level", "middle"}, {"bogus", 1}});
  ASSERT_EQ(errors.size(), 4U); // output type, level value, unknown bogus, missing limit_us
  const auto joined = errors[0] + errors[1] + errors[2] + errors[3];
  EXPECT_NE(joined.find("unknown parameter 'bogus'"), std::string::npos);
  EXPECT_NE(joined.find("missing parameter 'limit_us'"), std::string::npos);
  EXPECT_NE(joined.find("'output' must be a string"), std::string::npos);
  // Cross rule: crossings or setpoint, not both or neither.
  EXPECT_EQ(validate_check_params(k, json{{"output", "ls1"}, {"limit_us", 20}}).size(), 1U);
  EXPECT_FALSE(validate_check_params(*find_check_kind("pulse_width"), json{{"line", "x"}, {"min_pulses", -1}})
                   .empty());
}

TEST(Registry, ThroughputFromThePositionFunctionAndASetpoint) {
  // Position 1 count/ms; setpoint 5 -> crossing at 5 ms; output high at 5.015 ms.
  Capture c;
  c.position = [](Nanos t) { return static_cast<double>(t.count()) / 1e6; };
  c.lines["dut.ls1"] = {{5_ms + 15_us, Level::High}};
  c.begin = 0_ms;
  c.end = 10_ms;
  const auto r =
      run_check("ls1-throughput", "throughput", c,
                json{{"output", "dut.ls1"}, {"limit_us", 20}, {"setpoint", 5}, {"direction", "rising"}});
  EXPECT_EQ(r.check, "ls1-throughput");
  EXPECT_EQ(r.kind, "throughput");
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "ls1-throughput.max").value, 15.0);
}

TEST(Registry, BadParametersOrAMissingLineAreErrorsNotFailures) {
  Capture c;
  auto r = run_check("x", "throughput", c, json{{"output", "dut.ls1"}});
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
  r = run_check("x", "throughput", c,
                json{{"output", "dut.ls1"}, {"limit_us", 20}, {"crossings_us", {1000}}});
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
  EXPECT_NE(r.measurements[0].detail.find("no line named 'dut.ls1'"), std::string::npos);
  EXPECT_EQ(run_check("x", "nonsense", c, json::object()).outcome(), rig::Outcome::Error);
  // Debounce without the executive's bisection cannot be judged.
  r = run_check("d", "debounce", c,
                json{{"filter_us", 500},
                     {"tolerance_us", 10},
                     {"narrow_us", 1},
                     {"wide_us", 2000},
                     {"input", "in1"},
                     {"output", "out1"}});
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
}

TEST(Registry, DebouncePlanThenCheck) {
  const json p{{"filter_us", 500},   {"tolerance_us", 10}, {"narrow_us", 1},      {"wide_us", 2000},
               {"resolution_us", 1}, {"input", "rig.in1"}, {"output", "dut.out1"}};
  const BisectionPlan plan = debounce_plan(p);
  EXPECT_EQ(plan.narrow, 1_us);
  EXPECT_EQ(plan.wide, 2_ms);
  EXPECT_EQ(plan.resolution, 1_us);
  EXPECT_EQ(plan.input, "rig.in1");
  Capture c;
  // A board with a 503 us filter: inside 500 ± 10.
  c.bisection = bisect_boundary([](Nanos w) { return w >= 503_us; }, plan.narrow, plan.wide, plan.resolution);
  const auto r = run_check("in1-debounce", "debounce", c, p);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_NEAR(find(r, "in1-debounce.boundary").value, 503.0, 1.0);
}

TEST(Registry, BrakeFromTheBrakeLineAndTheReportedWord) {
  Capture c;
  c.lines["rig.brake"] = {{100_ms, Level::Low}};
  c.lines["dut.stop_fault"] = {};
  c.motion = {{0_ms, 0.0}, {200_ms, 10.0}, {250_ms, 12.0}};
  c.observations = {{"dut.stop_time", 151.0, "ms", 500_ms}};
  c.end = 600_ms;
  const json p{{"limit_ms", 200},
               {"brake_line", "rig.brake"},
               {"reported", "dut.stop_time"},
               {"fault_output", "dut.stop_fault"}};
  const auto r = run_check("brake", "brake_stop_time", c, p);
  EXPECT_EQ(find(r, "brake.stop_time").value, 150.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
}

} // namespace
} // namespace hilrig::checks
