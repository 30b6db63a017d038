// Issue 16 item 6: results.json is the one source of truth, junit.xml and report.html are
// derived from it. In a fault run with several caught_by checks (any one failing catches
// it) the catching checks read "caught", the others "not judged"; a passing campaign shows
// no failure anywhere. Item 7: merge refuses shards of another campaign revision or tool.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "rig/results/junit.hpp"
#include "rig/results/merge.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::rig {
namespace {

// A fault run whose fault two checks may catch: the throughput check fails (35 us against
// 20 us), the advance check passes, and a third check nobody named passes too.
CampaignResult two_catchers(bool caught) {
  CampaignResult c;
  c.campaign = "two-catchers";
  c.planned_runs = 2;
  c.runs = {test::nominal_run(0, 10.0), test::fault_run(1, "slow", caught)};
  c.runs[1].must_catch = {"ls1-throughput", "ls1-advance"};
  CheckResult extra = c.runs[1].checks[1];
  extra.check = "ls1-other";
  c.runs[1].checks.push_back(extra);
  finalize(c);
  return c;
}

TEST(Verdict, CatchingCheckReadsCaughtTheOthersNotJudged) {
  const CampaignResult c = two_catchers(true);
  ASSERT_EQ(c.verdict, Outcome::Pass);
  const RunResult& fault = c.runs[1];
  EXPECT_EQ(fault.outcome, Outcome::Pass);
  EXPECT_EQ(fault.checks[0].judgement, Judgement::Caught);
  EXPECT_EQ(fault.checks[1].judgement, Judgement::NotJudged); // named, passed: another caught it
  EXPECT_EQ(fault.checks[2].judgement, Judgement::NotJudged);
  EXPECT_EQ(c.totals.checks_failed, 0U);
  EXPECT_EQ(c.totals.checks_caught, 1U);
  EXPECT_EQ(c.totals.checks_not_judged, 2U);
  EXPECT_EQ(c.totals.checks_passed, 2U);

  const nlohmann::json j = to_json(c);
  EXPECT_EQ(j["runs"][1]["checks"][0]["outcome"], "caught");
  EXPECT_EQ(j["runs"][1]["checks"][0]["measured"], "fail");
  EXPECT_EQ(j["runs"][1]["checks"][1]["outcome"], "not judged");
  EXPECT_EQ(j["runs"][1]["checks"][2]["outcome"], "not judged");

  // junit: no failure or error in a passing campaign; the not-judged checks are skipped.
  const std::string x = to_junit_xml(c);
  EXPECT_EQ(hilrig::test::count_of(x, "<failure "), 0U) << x;
  EXPECT_EQ(hilrig::test::count_of(x, "<error "), 0U);
  EXPECT_EQ(hilrig::test::count_of(x, "<skipped "), 2U);
  EXPECT_NE(x.find("failures=\"0\" errors=\"0\""), std::string::npos);
  EXPECT_NE(x.find("not judged: fault &#39;slow&#39; was caught by ls1-throughput"), std::string::npos) << x;

  // report: nothing red; the words are caught and not judged.
  const std::string h = to_report_html(c);
  EXPECT_EQ(hilrig::test::count_of(h, "class=\"fail\""), 0U);
  // No edge drawn in the fail colour either (the histogram's dashed limit line is red by design).
  EXPECT_EQ(hilrig::test::count_of(h, "stroke=\"#cf222e\" stroke-width=\"2\""), 0U);
  EXPECT_NE(h.find("<span class=\"caught\">caught</span>"), std::string::npos);
  EXPECT_NE(h.find("<span class=\"not-judged\">not judged</span>"), std::string::npos);
}

TEST(Verdict, AFaultNobodyCaughtFailsEveryNamedCheck) {
  const CampaignResult c = two_catchers(false);
  EXPECT_EQ(c.verdict, Outcome::Fail);
  EXPECT_EQ(c.runs[1].checks[0].judgement, Judgement::Fail);
  EXPECT_EQ(c.runs[1].checks[1].judgement, Judgement::Fail);
  EXPECT_EQ(c.runs[1].checks[2].judgement, Judgement::NotJudged);
  const std::string x = to_junit_xml(c);
  EXPECT_EQ(hilrig::test::count_of(x, "<failure "), 2U);
  EXPECT_NE(x.find("fault &#39;slow&#39; not caught"), std::string::npos);
}

TEST(Verdict, TheWordsRoundTripThroughResultsJson) {
  const CampaignResult c = two_catchers(true);
  const CampaignResult back = campaign_from_json(nlohmann::json::parse(to_json_text(c)));
  EXPECT_EQ(to_json_text(back), to_json_text(c));
  EXPECT_EQ(to_junit_xml(back), to_junit_xml(c));
  EXPECT_EQ(to_report_html(back), to_report_html(c));
}

TEST(Verdict, ACheckWithNoMeasurementIsAnError) {
  CampaignResult c;
  c.campaign = "empty";
  c.planned_runs = 1;
  c.runs = {test::nominal_run(0, 10.0)};
  c.runs[0].checks[1].measurements.clear();
  finalize(c);
  EXPECT_EQ(c.runs[0].checks[1].judgement, Judgement::Error);
  EXPECT_EQ(c.verdict, Outcome::Error);
  EXPECT_EQ(hilrig::test::count_of(to_junit_xml(c), "<error "), 1U);
}

std::vector<CampaignResult> two_shards() {
  CampaignResult whole = test::sample_campaign(4);
  whole.campaign_sha256 = std::string(64, 'a');
  whole.tool_version = "0.1.0";
  std::vector<CampaignResult> out;
  for (std::uint32_t k = 0; k < 2; ++k) {
    CampaignResult s = whole;
    s.shard = Shard{k, 2};
    s.runs.clear();
    for (const auto& r : whole.runs)
      if (r.index % 2 == k) s.runs.push_back(r);
    s.planned_runs = s.runs.size();
    finalize(s);
    out.push_back(campaign_from_json(nlohmann::json::parse(to_json_text(s))));
  }
  return out;
}

std::string merge_error(std::vector<CampaignResult> shards) {
  try {
    (void)merge_shards(std::move(shards));
    return "merged";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

// Item 7: shards of two revisions of a campaign (same name, different limits) merged into a
// "complete" result. The file's SHA-256 and the tool version travel in each results.json.
TEST(Merge, RefusesShardsOfAnotherCampaignRevisionOrToolVersion) {
  auto shards = two_shards();
  EXPECT_EQ(merge_error(shards), "merged");
  EXPECT_EQ(merge_shards(shards).campaign_sha256, std::string(64, 'a'));
  auto revised = shards;
  revised[1].campaign_sha256 = std::string(64, 'b');
  const std::string why = merge_error(revised);
  EXPECT_NE(why.find(std::string(64, 'a')), std::string::npos) << why;
  EXPECT_NE(why.find(std::string(64, 'b')), std::string::npos) << why;
  EXPECT_NE(why.find("campaign file"), std::string::npos) << why;
  auto other_tool = shards;
  other_tool[0].tool_version = "0.0.9";
  const std::string why_tool = merge_error(other_tool);
  EXPECT_NE(why_tool.find("0.0.9"), std::string::npos) << why_tool;
  EXPECT_NE(why_tool.find("0.1.0"), std::string::npos) << why_tool;
}

TEST(ResultsJson, CarriesTheCampaignHashAndToolVersion) {
  CampaignResult c = test::sample_campaign(2);
  c.campaign_sha256 = std::string(64, 'c');
  c.tool_version = "0.1.0";
  const nlohmann::json j = to_json(c);
  EXPECT_EQ(j["campaign_sha256"], std::string(64, 'c'));
  EXPECT_EQ(j["tool_version"], "0.1.0");
  const CampaignResult back = campaign_from_json(j);
  EXPECT_EQ(back.campaign_sha256, c.campaign_sha256);
  EXPECT_EQ(back.tool_version, "0.1.0");
}

} // namespace
} // namespace hilrig::rig
