// Every shipped SMD23E campaign (campaigns/smd23e/*.toml) through the executive on the
// virtual SMD23E: the nominal runs pass, every fault-injection run is caught by the check
// the file names. The limits live in the campaign files, worked out by hand from the spec.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

std::string campaign_dir() { return std::string(HILRIG_SOURCE_DIR) + "/campaigns/smd23e"; }

std::string shipped(const std::string& name) { return campaign_dir() + "/" + name; }

std::vector<std::string> every_campaign() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(campaign_dir()))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

rig::CampaignResult run_everything(const Campaign& c) {
  return Executive(c).run_all(c.runs, c.seed, rig::Shard{0, 1});
}

// Why a run did not pass: its error, or its failing measurements.
std::string explain(const rig::RunResult& run) {
  std::string why = run.error;
  for (const auto& check : run.checks)
    for (const auto& m : check.measurements)
      if (m.outcome != Outcome::Pass)
        why += "\n  " + m.name + " = " + std::to_string(m.value) + ": " + m.detail;
  return why;
}

const rig::Measurement* find(const rig::RunResult& run, const std::string& name) {
  for (const auto& check : run.checks)
    for (const auto& m : check.measurements)
      if (m.name == name) return &m;
  return nullptr;
}

TEST(Smd23eCampaigns, EveryShippedCampaignPassesAndCatchesItsFaults) {
  const std::vector<std::string> files = every_campaign();
  ASSERT_GE(files.size(), 6U);
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const Campaign c = load_campaign(file);
    const rig::CampaignResult r = run_everything(c);
    // At least one nominal run and one run per fault: a verdict on nothing is no verdict.
    EXPECT_EQ(r.runs.size(), 1U + c.faults.size());
    for (const auto& run : r.runs) {
      if (run.fault.empty()) {
        EXPECT_TRUE(run.error.empty()) << run.error;
        for (const auto& check : run.checks)
          EXPECT_EQ(check.outcome(), Outcome::Pass) << check.check << explain(run);
      } else {
        EXPECT_TRUE(rig::caught(run)) << "fault " << run.fault << " not caught";
      }
    }
    EXPECT_EQ(r.totals.faults, r.totals.faults_caught);
    EXPECT_EQ(r.verdict, Outcome::Pass);
  }
}

TEST(Smd23eCampaigns, ProfileMeasuresTheMovesOnTheShaft) {
  const Campaign c = load_campaign(shipped("smd23e_profile.toml"));
  const rig::CampaignResult r = run_everything(c);
  ASSERT_EQ(r.runs.size(), 1U);
  const rig::RunResult& run = r.runs[0];
  // Trapezoid: T = 481 ms, cruise at exactly v_p = 10000 steps/s (100 us a step, to 1 ns).
  const auto* duration = find(run, "trapezoid.duration");
  ASSERT_NE(duration, nullptr);
  EXPECT_NEAR(duration->value, 481.0, 1.0);
  const auto* peak = find(run, "trapezoid.peak_speed");
  ASSERT_NE(peak, nullptr);
  EXPECT_NEAR(peak->value, 10000.0, 1.0);
  // Triangle: T = 136.205 ms, peak sqrt(61e6) = 7810.25 steps/s.
  const auto* tri = find(run, "triangle.duration");
  ASSERT_NE(tri, nullptr);
  EXPECT_NEAR(tri->value, 136.205, 1.0);
  EXPECT_EQ(find(run, "triangle.steps")->value, 600.0);
}

TEST(Smd23eCampaigns, FaultCampaignCatchesEachVariantWithItsCheck) {
  const Campaign c = load_campaign(shipped("smd23e_faults.toml"));
  const rig::CampaignResult r = run_everything(c);
  ASSERT_EQ(r.runs.size(), 5U); // nominal + 4 variants
  EXPECT_EQ(r.totals.faults, 4U);
  EXPECT_EQ(r.totals.faults_caught, 4U);
  std::set<std::string> seen;
  for (const auto& run : r.runs) {
    if (run.fault.empty()) continue;
    seen.insert(run.fault);
    if (run.fault == "wrong-acceleration") {
      // Half A and D: T = 562 ms (worked out in the file), over the 487.81 ms limit.
      EXPECT_NEAR(find(run, "trapezoid.duration")->value, 562.0, 1.0);
      EXPECT_EQ(find(run, "trapezoid.duration")->outcome, Outcome::Fail);
    } else if (run.fault == "lost-steps") {
      // One step in 100 lost: 40 of 4000.
      EXPECT_EQ(find(run, "trapezoid_distance.steps")->value, 3960.0);
      EXPECT_EQ(find(run, "trapezoid_distance.steps")->outcome, Outcome::Fail);
    } else if (run.fault == "late-stop") {
      // 20 ms late at 10000 steps/s: 200 steps more than 495, 20 ms more than 90.
      EXPECT_EQ(find(run, "hold_stop.steps")->value, 695.0);
      EXPECT_NEAR(find(run, "hold_stop.duration")->value, 110.0, 1.0);
    } else if (run.fault == "ignored-limit") {
      // The jog runs on at 10000 steps/s for the 150 ms left after the limit.
      EXPECT_NEAR(find(run, "limit_stop.steps")->value, 1500.0, 1.0);
      EXPECT_EQ(find(run, "limit_stop.steps")->outcome, Outcome::Fail);
    }
  }
  EXPECT_EQ(seen, (std::set<std::string>{"wrong-acceleration", "lost-steps", "late-stop", "ignored-limit"}));
}

TEST(Smd23eCampaigns, HomingEndsAtZeroAfterTwoReversals) {
  const Campaign c = load_campaign(shipped("smd23e_homing.toml"));
  const rig::CampaignResult r = run_everything(c);
  ASSERT_EQ(r.runs.size(), 1U);
  const rig::RunResult& run = r.runs[0];
  EXPECT_EQ(find(run, "sequence.reversals")->value, 2.0);
  // The creep runs at v_s = 1000 steps/s: 1 ms a step.
  EXPECT_NEAR(find(run, "creep.peak_speed")->value, 1000.0, 1.0);
  EXPECT_EQ(find(run, "position_lower")->value, 0.0);
}

TEST(Smd23eCampaigns, SameSeedGivesTheSameTrace) {
  const Campaign c = load_campaign(shipped("smd23e_stops.toml"));
  const Executive e(c);
  const RunOutput a = e.run(c.runs[0]);
  const RunOutput b = e.run(c.runs[0]);
  ASSERT_NE(a.trace, nullptr);
  ASSERT_NE(b.trace, nullptr);
  EXPECT_EQ(a.trace->content_hash(), b.trace->content_hash());
  EXPECT_FALSE(a.trace->edges_of("shaft.step").empty());
}

} // namespace
} // namespace hilrig::campaign
