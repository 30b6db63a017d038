#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "rig/results/merge.hpp"
#include "rig/results/results_json.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

// Shard k of n holds the runs whose index % n == k (a Slurm array of n tasks), each shard
// passed through its own results.json text as it would be between machines.
std::vector<CampaignResult> shard(const CampaignResult& whole, std::uint32_t n) {
  std::vector<CampaignResult> out;
  for (std::uint32_t k = 0; k < n; ++k) {
    CampaignResult s = whole;
    s.shard = Shard{k, n};
    s.runs.clear();
    for (const auto& r : whole.runs) {
      if (r.index % n == k) s.runs.push_back(r);
    }
    s.planned_runs = s.runs.size();
    finalize(s);
    out.push_back(campaign_from_json(nlohmann::json::parse(to_json_text(s))));
  }
  return out;
}

TEST(Merge, ShardsMergeToTheUnshardedResult) {
  const CampaignResult whole = test::sample_campaign(10);
  for (std::uint32_t n : {1U, 2U, 3U, 4U}) {
    auto shards = shard(whole, n);
    std::reverse(shards.begin(), shards.end()); // given in any order
    const CampaignResult merged = merge_shards(shards);
    EXPECT_TRUE(same_content(merged, whole)) << n << " shards";
    EXPECT_EQ(to_json_text(merged), to_json_text(whole)) << n << " shards";
  }
}

TEST(Merge, RefusesMissingDuplicateOrForeignShards) {
  const CampaignResult whole = test::sample_campaign(9);
  auto shards = shard(whole, 3);
  auto missing = shards;
  missing.pop_back();
  EXPECT_THROW((void)merge_shards(missing), std::invalid_argument);
  auto twice = shards;
  twice[2] = twice[1];
  EXPECT_THROW((void)merge_shards(twice), std::invalid_argument);
  auto foreign = shards;
  foreign[1].seed = 7;
  EXPECT_THROW((void)merge_shards(foreign), std::invalid_argument);
  auto overlap = shards;
  overlap[1].runs.push_back(overlap[0].runs[0]);
  EXPECT_THROW((void)merge_shards(overlap), std::invalid_argument);
  EXPECT_THROW((void)merge_shards({}), std::invalid_argument);
}

} // namespace
} // namespace hilrig::rig
