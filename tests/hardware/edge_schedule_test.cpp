// The RT loop's schedule is what the virtual run drives: a known motion (1000 counts/s, so
// count k at k ms) with its stimuli and signal faults gives the edges worked out by hand
// below, and the same edges the virtual run puts on its bus lines.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/hardware/drive_plan.hpp"
#include "rig/hardware/edge_schedule.hpp"
#include "tests/hardware/loop_campaign.hpp"

namespace hilrig::hardware {
namespace {

constexpr Nanos us(std::int64_t v) { return Nanos{v * 1'000}; }

struct Fixture {
  campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  RigConfig rig = parse_rig_config(test::kLoopRig, "rig.toml");
  DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  campaign::RunInputs in;
  Fixture() {
    in.scenario = &c.points.at(0);
    in.variant = "nominal";
    in.seed = 7;
  }
};

TEST(EdgeSchedule, KnownMotionGivesTheEdgesWorkedByHand) {
  Fixture f;
  // Outputs in wiring order: the board inputs enc.A, enc.B, en.
  ASSERT_EQ(f.plan.outputs.size(), 3U);
  EXPECT_EQ(f.plan.outputs[0].rig, "enc.A");
  EXPECT_EQ(f.plan.outputs[1].rig, "enc.B");
  EXPECT_EQ(f.plan.outputs[2].rig, "en");
  const EdgeSchedule s = build_schedule(f.in, f.plan);
  constexpr std::uint16_t A = 0, B = 1, EN = 2;
  const Level H = Level::High, L = Level::Low;
  // X4 from count 0 (A and B low): count 1 raises A, 2 raises B, 3 drops A, 4 drops B, ...
  // EN goes high at 0.5 ms. enc.B loses every 2nd edge before 5 ms: the one at 4 ms, so B
  // stays high and count 6 (B up) is no edge. A glitches low 6.5..6.6 ms, is stuck high
  // 7.5..8.5 ms (count 7 dropped it at 7 ms) and then goes back to its level, low.
  const std::vector<ScheduledEdge> expected{
      {us(500), EN, H}, {us(1000), A, H}, {us(2000), B, H},  {us(3000), A, L}, {us(5000), A, H},
      {us(6500), A, L}, {us(6600), A, H}, {us(7000), A, L},  {us(7500), A, H}, {us(8000), B, L},
      {us(8500), A, L}, {us(9000), A, H}, {us(10000), B, H},
  };
  ASSERT_EQ(s.edges.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    // The edge times are solved in floating point: a nanosecond of rounding is allowed.
    EXPECT_LE(std::abs((s.edges[i].time - expected[i].time).count()), 1) << "edge " << i;
    EXPECT_EQ(s.edges[i].line, expected[i].line) << "edge " << i;
    EXPECT_EQ(s.edges[i].level, expected[i].level) << "edge " << i;
  }
  // Initial levels: count 0 has A and B low; EN starts low.
  for (const PlannedLine& p : f.plan.outputs) EXPECT_EQ(p.initial, Level::Low) << p.rig;
}

TEST(EdgeSchedule, SameEdgesAsTheVirtualRunDrives) {
  Fixture f;
  const EdgeSchedule s = build_schedule(f.in, f.plan);
  const campaign::VirtualRun v = campaign::run_virtual(f.in);
  for (std::size_t line = 0; line < f.plan.outputs.size(); ++line) {
    std::vector<Edge> scheduled;
    for (const ScheduledEdge& e : s.edges)
      if (e.line == line) scheduled.push_back(Edge{e.time, e.level});
    EXPECT_EQ(scheduled, v.trace->edges_of(f.plan.outputs[line].rig)) << f.plan.outputs[line].rig;
  }
}

TEST(EdgeSchedule, ProbeAndFaultsOfTheRunAreScheduled) {
  Fixture f;
  campaign::Stimulus probe;
  probe.kind = campaign::StimulusKind::Pulse;
  probe.at = us(4200);
  probe.line = "en";
  probe.level = Level::Low;
  probe.width = us(30);
  f.in.probe = probe;
  const EdgeSchedule s = build_schedule(f.in, f.plan);
  std::vector<ScheduledEdge> en;
  for (const ScheduledEdge& e : s.edges)
    if (e.line == 2) en.push_back(e);
  ASSERT_EQ(en.size(), 3U); // up at 0.5 ms, then the probe: low at 4.2 ms for 30 us
  EXPECT_EQ(en[1].time, us(4200));
  EXPECT_EQ(en[1].level, Level::Low);
  EXPECT_EQ(en[2].time, us(4230));
  EXPECT_EQ(en[2].level, Level::High);
}

// A [plant] closes the loop through the board's outputs as they happen, which a schedule
// computed before the run cannot: the hardware backend refuses it rather than play an
// open-loop guess (docs/plants.md).
TEST(EdgeSchedule, APlantScenarioIsRefused) {
  std::string text = test::kLoopCampaign;
  const std::string motion =
      "[motion]\n[[motion.move]]\nkind = \"constant\"\nspeed_rpm = 150\nduration = \"10ms\"";
  const std::size_t at = text.find(motion);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, motion.size(), "[plant]\nkind = \"rotary_axis\"\nstart_speed = 15.0");
  const campaign::Campaign c = campaign::parse_campaign(text, "plant.toml");
  ASSERT_TRUE(c.points.at(0).plant.has_value());
  const RigConfig rig = parse_rig_config(test::kLoopRig, "rig.toml");
  const DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  campaign::RunInputs in;
  in.scenario = &c.points.at(0);
  in.variant = "nominal";
  EXPECT_THROW((void)build_schedule(in, plan), campaign::RigFault);
}

} // namespace
} // namespace hilrig::hardware
