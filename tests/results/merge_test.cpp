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

std::string merge_error(std::vector<CampaignResult> shards, const std::vector<std::string>& files) {
  try {
    (void)merge_shards(std::move(shards), files);
    return "merged";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

// Issue 18 follow-up: shards of one campaign run on two boards (`[dut] serial`) or at two
// stations (`--station`) are not one board's complete result. The message names both values
// and both shard files.
TEST(Merge, RefusesShardsOfAnotherBoardOrStationNamingBothValuesAndFiles) {
  CampaignResult whole = test::sample_campaign(6);
  whole.dut_serial = "SN-0042";
  whole.station = "bench-a";
  const std::vector<std::string> files{"shard0/results.json", "shard1/results.json"};
  const auto shards = shard(whole, 2);
  EXPECT_EQ(merge_error(shards, files), "merged");
  const CampaignResult merged = merge_shards(shards, files);
  EXPECT_EQ(merged.dut_serial, "SN-0042");
  EXPECT_EQ(merged.station, "bench-a");

  auto other_board = shards;
  other_board[1].dut_serial = "SN-0043";
  std::string why = merge_error(other_board, files);
  for (const char* part :
       {"'SN-0042'", "'SN-0043'", "shard0/results.json", "shard1/results.json", "[dut] serial"})
    EXPECT_NE(why.find(part), std::string::npos) << part << " in: " << why;

  auto other_station = shards;
  other_station[0].station = "bench-b";
  why = merge_error(other_station, files);
  for (const char* part :
       {"'bench-a'", "'bench-b'", "shard0/results.json", "shard1/results.json", "--station"})
    EXPECT_NE(why.find(part), std::string::npos) << part << " in: " << why;

  // A shard run without --station against one with it: "none" names the missing value.
  auto unnamed = shards;
  unnamed[1].station.clear();
  why = merge_error(unnamed, files);
  EXPECT_NE(why.find("station none"), std::string::npos) << why;

  // Given in another order, each file still names its own shard.
  auto reversed = other_board;
  std::reverse(reversed.begin(), reversed.end());
  why = merge_error(reversed, {files[1], files[0]});
  EXPECT_NE(why.find("shard 1 (shard1/results.json) ran on DUT serial 'SN-0043'"), std::string::npos) << why;
}

TEST(Merge, CarriesTheShardsTracePolicyAndRefusesShardsOfAnother) {
  CampaignResult whole = test::sample_campaign(6);
  for (const TracePolicy p : {TracePolicy::All, TracePolicy::Failed, TracePolicy::None}) {
    whole.trace_policy = p;
    EXPECT_EQ(merge_shards(shard(whole, 3)).trace_policy, p) << to_string(p);
  }
  auto mixed = shard(whole, 3); // --trace none
  mixed[2].trace_policy = TracePolicy::Failed;
  try {
    (void)merge_shards(mixed);
    ADD_FAILURE() << "merged shards of different trace policies";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "shard 2 ran with --trace failed, shard 0 with --trace none: shards of "
                           "different trace policies do not merge");
  }
}

TEST(TracePolicy, NamesReadBackAndAnUnknownNameIsNone) {
  for (const std::string& name : trace_policy_names()) {
    const auto p = trace_policy_named(name);
    ASSERT_TRUE(p) << name;
    EXPECT_EQ(to_string(*p), name);
  }
  EXPECT_EQ(trace_policy_names(), (std::vector<std::string>{"all", "failed", "none"}));
  EXPECT_FALSE(trace_policy_named("All"));
  EXPECT_FALSE(trace_policy_named(""));
  // Which runs keep their trace: (first run, passed) under each policy.
  EXPECT_TRUE(keeps_trace(TracePolicy::All, true, true));
  EXPECT_TRUE(keeps_trace(TracePolicy::All, false, false));
  EXPECT_FALSE(keeps_trace(TracePolicy::All, false, true));
  EXPECT_FALSE(keeps_trace(TracePolicy::Failed, true, true));
  EXPECT_TRUE(keeps_trace(TracePolicy::Failed, true, false));
  EXPECT_TRUE(keeps_trace(TracePolicy::Failed, false, false));
  EXPECT_FALSE(keeps_trace(TracePolicy::None, true, false));
  EXPECT_FALSE(keeps_trace(TracePolicy::None, false, false));
}

// Every refusal names the shard files it is about, so a nightly job's log says which artifact to
// re-fetch: the two holding one shard index, the two holding one run, the two counts that differ.
TEST(Merge, RefusalsOfDuplicateOverlappingOrMiscountedShardsNameBothFiles) {
  const CampaignResult whole = test::sample_campaign(9);
  const auto shards = shard(whole, 3);
  const std::vector<std::string> files{"a/results.json", "b/results.json", "c/results.json"};
  EXPECT_EQ(merge_error(shards, files), "merged");

  auto twice = shards;
  twice[2] = twice[1];
  std::string why = merge_error(twice, files);
  for (const char* part : {"shard 1 given twice", "b/results.json", "c/results.json"})
    EXPECT_NE(why.find(part), std::string::npos) << part << " in: " << why;

  // Shard K of N holds the runs whose index mod N is K: shard 0's run in shard 2 is refused
  // there, naming the file; a run twice in one file too.
  auto overlap = shards;
  overlap[2].runs.push_back(overlap[0].runs[1]);
  why = merge_error(overlap, files);
  const std::string run = "run " + std::to_string(overlap[0].runs[1].index) +
                          " in shard 2 (c/results.json): shard 2 of 3 holds the runs whose index mod 3 is 2";
  EXPECT_NE(why.find(run), std::string::npos) << why;
  auto doubled = shards;
  doubled[1].runs.push_back(doubled[1].runs[0]);
  why = merge_error(doubled, files);
  EXPECT_NE(why.find("run " + std::to_string(doubled[1].runs[0].index) +
                     " appears twice in shard 1 (b/results.json)"),
            std::string::npos)
      << why;
  // An index beyond the plan (9 runs: 0 .. 8) is no run of this campaign, in its residue or not.
  auto beyond = shards;
  beyond[0].runs.back().index = 9;
  why = merge_error(beyond, files);
  EXPECT_NE(why.find("run 9 in shard 0 (a/results.json): the campaign plans 9 runs, 0 .. 8"),
            std::string::npos)
      << why;

  auto miscounted = shards;
  miscounted[1].shard.count = 4;
  why = merge_error(miscounted, files);
  for (const char* part : {"one of 4 shards", "one of 3", "a/results.json", "b/results.json"})
    EXPECT_NE(why.find(part), std::string::npos) << part << " in: " << why;
}

} // namespace
} // namespace hilrig::rig
