// The shipped ANS1 campaigns (campaigns/ans1/*.toml) end to end on the virtual ANS1: every
// campaign passes on the correct model, the fault campaign catches every fault variant the
// model has, two runs with one seed give the same results.json bytes, and merged shards
// equal the unsharded run.

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/ans1/variants.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/results/merge.hpp"
#include "rig/results/results_json.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

std::string ans1_dir() { return test::campaign_dir("ans1"); }
std::vector<std::string> ans1_campaigns() { return test::campaigns_of("ans1"); }
using test::failures;

class Ans1Campaign : public ::testing::TestWithParam<std::string> {};

TEST_P(Ans1Campaign, PassesOnTheCorrectModelAndCatchesEveryFault) {
  const Campaign c = load_campaign(GetParam());
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), c.runs.size());
  EXPECT_EQ(r.verdict, Outcome::Pass) << failures(r);
  EXPECT_EQ(r.totals.faults_caught, c.faults.size()) << failures(r);
}

std::string file_stem(const ::testing::TestParamInfo<std::string>& info) {
  return std::filesystem::path(info.param).stem().string();
}

INSTANTIATE_TEST_SUITE_P(Shipped, Ans1Campaign, ::testing::ValuesIn(ans1_campaigns()), file_stem);

TEST(Ans1Campaigns, TheShippedSetCoversEveryArea) {
  // One file per area the spec's test plan names (spec/ans1.md §1: latency, brake, die
  // protection, counters, advances, timers).
  std::set<std::string> stems;
  for (const auto& f : ans1_campaigns()) stems.insert(std::filesystem::path(f).stem().string());
  for (const char* want : {"ans1_throughput", "ans1_advances", "ans1_brake", "ans1_stitch_wrap", "ans1_timed",
                           "ans1_die_protection", "ans1_counters", "ans1_resolver", "ans1_faults"})
    EXPECT_TRUE(stems.contains(want)) << want;
}

TEST(Ans1Campaigns, TheFaultCampaignInjectsEveryVariantOfTheModel) {
  // A variant the fault campaign leaves out is a fault nobody has shown a check catches.
  const Campaign c = load_campaign(ans1_dir() + "/ans1_faults.toml");
  std::set<std::string> injected;
  for (const auto& f : c.faults)
    if (f.variant) injected.insert(*f.variant);
  for (const auto& v : models::ans1::kVariantNames) {
    if (v.variant == models::ans1::Variant::Correct) continue;
    EXPECT_TRUE(injected.contains(std::string(v.name))) << v.name << " is not injected";
  }
}

TEST(Ans1Campaigns, AdvancesFollowW13AtEverySpeed) {
  // W-13 (ans1-examples.md, L893): a 10 ms lead at FSC 360 is 6 counts at 100 RPM and 9 at
  // 150 RPM; at 600 RPM 10 ms * 3600 counts/s = 36. From = 100 fires at 94, 91 and 64
  // (+-1 count for the model's speed jitter; the rig's position at the edge is exact).
  const Campaign c = load_campaign(ans1_dir() + "/ans1_advances.toml");
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 3U);
  const double fired_at[] = {94.0, 91.0, 64.0};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto* edge = test::find(r.runs[i], "lead.edge0");
    ASSERT_NE(edge, nullptr) << r.runs[i].name;
    EXPECT_NEAR(edge->value, fired_at[i], 1.0) << r.runs[i].name;
  }
}

TEST(Ans1Campaigns, ASlowBrakeTripsTheBoardsStopOverrunAndFailsTheLimit) {
  // ans1_brake.toml: brake applied at 125 ms; 6000 RPM/s stops in 100 ms, 1500 RPM/s in
  // 400 ms; the board's limit and the check's are 150 ms.
  const Campaign c = load_campaign(ans1_dir() + "/ans1_brake.toml");
  const rig::CampaignResult r = test::run_everything(c);
  ASSERT_EQ(r.runs.size(), 2U);
  const auto* fast = test::find(r.runs[0], "stop.stop_time");
  ASSERT_NE(fast, nullptr);
  EXPECT_GE(fast->value, 92.9); // the last count change: sqrt(2 / (400 * 100)) s before the stop
  EXPECT_LE(fast->value, 100.0);
  EXPECT_EQ(test::find(r.runs[0], "stop.fault_output")->value, 0.0);
  EXPECT_EQ(test::find(r.runs[0], "stop.reported")->outcome, Outcome::Pass);
  // The slow brake: the rig's stop time is over the limit (the fault is caught) and the
  // board's stop overrun output fired, as the check expects for an overrun.
  ASSERT_EQ(r.runs[1].fault, "slow_brake");
  const auto* slow = test::find(r.runs[1], "stop.stop_time");
  ASSERT_NE(slow, nullptr);
  EXPECT_GE(slow->value, 385.8); // sqrt(2 / (400 * 25)) s = 14.1 ms before the 400 ms stop
  EXPECT_LE(slow->value, 400.0);
  EXPECT_EQ(slow->outcome, Outcome::Fail);
  const auto* fired = test::find(r.runs[1], "stop.fault_output");
  ASSERT_NE(fired, nullptr);
  EXPECT_EQ(fired->value, 1.0);
  EXPECT_EQ(fired->outcome, Outcome::Pass);
  EXPECT_EQ(test::find(r.runs[1], "stop.reported")->outcome, Outcome::Pass);
  EXPECT_EQ(r.verdict, Outcome::Pass);
}

TEST(Ans1Campaigns, OneSeedGivesIdenticalResultsJsonBytes) {
  const Campaign c = load_campaign(ans1_dir() + "/ans1_faults.toml");
  const rig::CampaignResult a = test::run_everything(c);
  const rig::CampaignResult b = test::run_everything(c);
  EXPECT_EQ(rig::to_json_text(a), rig::to_json_text(b));
}

TEST(Ans1Campaigns, MergedShardsOfTheFaultCampaignEqualTheUnshardedRun) {
  const Campaign c = load_campaign(ans1_dir() + "/ans1_faults.toml");
  constexpr std::uint32_t kShards = 3;
  std::vector<rig::CampaignResult> parts;
  for (std::uint32_t k = 0; k < kShards; ++k)
    parts.push_back(Executive(c).run_all(shard(c.runs, k, kShards), c.seed, rig::Shard{k, kShards}));
  const rig::CampaignResult merged = rig::merge_shards(parts);
  const rig::CampaignResult whole = test::run_everything(c);
  EXPECT_TRUE(rig::same_content(merged, whole));
  EXPECT_EQ(rig::to_json_text(merged), rig::to_json_text(whole));
}

} // namespace
} // namespace hilrig::campaign
