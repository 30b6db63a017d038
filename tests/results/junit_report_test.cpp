#include <gtest/gtest.h>

#include <regex>

#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::rig {
namespace {

TEST(Junit, OneTestcasePerCheckPerRunWithCountsThatAddUp) {
  // Runs 0, 1 nominal (pass); run 2 fault caught (throughput passes as a testcase, advance
  // skipped); run 3 nominal but 21 us (fails); run 4 fault missed (throughput failure).
  CampaignResult c;
  c.campaign = "ans1 <sample>";
  c.planned_runs = 5;
  c.runs = {test::nominal_run(0, 10.0), test::nominal_run(1, 11.0), test::fault_run(2, "slow", true),
            test::nominal_run(3, 21.0), test::fault_run(4, "slow", false)};
  finalize(c);
  const std::string x = to_junit_xml(c);
  EXPECT_EQ(hilrig::test::count_of(x, "<testcase "), 10U);
  EXPECT_EQ(hilrig::test::count_of(x, "<testsuite "), 5U);
  EXPECT_EQ(hilrig::test::count_of(x, "<failure "), 2U);
  EXPECT_EQ(hilrig::test::count_of(x, "<skipped "), 2U);
  EXPECT_NE(x.find("<testsuites name=\"ans1 &lt;sample&gt;\" tests=\"10\" failures=\"2\" errors=\"0\""),
            std::string::npos);
  EXPECT_NE(x.find("fault &#39;slow&#39; not caught"), std::string::npos);
}

// Campaign "x" of `planned` runs with one nominal run, throughput max `max_us` (limit 20 us);
// not finalized, so a test can change a measurement first.
CampaignResult junit_campaign(double max_us, std::size_t planned) {
  CampaignResult c;
  c.campaign = "x";
  c.planned_runs = planned;
  c.runs = {test::nominal_run(0, max_us)};
  return c;
}

TEST(Junit, AFailureMessageNamesTheValueMeasuredAndItsLimits) {
  // Jenkins shows a testcase's failure `message` as its "Error Message" (the body is the
  // stack trace, folded away): it must say what was measured against which limit, not only
  // where. A run at 21.000000000000004 us against the 20 us limit fails, without float noise.
  CampaignResult c = junit_campaign(21.000000000000004, 1);
  finalize(c);
  const std::string x = to_junit_xml(c);
  EXPECT_NE(x.find("<failure message=\"ls1-throughput.max = 21 us, limits [- .. 20] us, measured fail: "
                   "hand-made\""),
            std::string::npos)
      << x;
}

// A value whose excess needs more than 9 significant digits still reads beyond its limit: a
// stop time of 1000.000001 ms (1 ns over) is not "1000 ms" beside a limit of 1000 ms.
TEST(Junit, AValueJustBeyondItsLimitReadsBeyondItInTheMessage) {
  CampaignResult c = junit_campaign(10.0, 1);
  Measurement& stop = c.runs[0].checks[0].measurements.back();
  stop.name = "ls1-throughput.stop";
  stop.unit = "ms";
  stop.value = 1000.000001;
  stop.upper = 1000.0;
  stop.outcome = Outcome::Fail;
  finalize(c);
  const std::string x = to_junit_xml(c);
  EXPECT_NE(x.find("<failure message=\"ls1-throughput.stop = 1000.000001 ms, limits [- .. 1000] ms"),
            std::string::npos)
      << x;
}

TEST(Junit, AnIncompleteCampaignIsAnErrorThoughEveryRunItHasPassed) {
  // A run killed after 1 of 3 runs, folded from its run log (docs/campaigns.md, "Run count
  // scaling"): results.json says complete false, verdict error. junit.xml must not read green
  // to a CI server that reads only it: the missing runs are one error, in the suite's too.
  CampaignResult c = junit_campaign(10.0, 3);
  finalize(c);
  ASSERT_FALSE(c.complete);
  ASSERT_EQ(c.verdict, Outcome::Error);
  const std::string x = to_junit_xml(c);
  EXPECT_NE(x.find("<testsuites name=\"x\" tests=\"3\" failures=\"0\" errors=\"1\""), std::string::npos) << x;
  EXPECT_NE(x.find("<error message=\"incomplete: 2 of 3 planned runs have no result"), std::string::npos)
      << x;
  const std::vector<JunitCampaign> suite = {{&c, "x.toml", {}, runs_of(c), nullptr, {}}};
  const std::string s = to_junit_suite_xml("nightly", suite);
  EXPECT_NE(s.find("<testsuites name=\"nightly\" tests=\"3\" failures=\"0\" errors=\"1\""), std::string::npos)
      << s;
  const JunitSuiteBody body = junit_suite_body(c, runs_of(c), {});
  EXPECT_EQ(body.counts.errored, 1U);
  EXPECT_EQ(hilrig::test::count_of(body.testcases, "<error "), 1U);

  // report.html says why at the top, in the same words, not only "(incomplete)" in its totals.
  EXPECT_NE(
      to_report_html(c).find("<p class=\"error\">Verdict error: incomplete: 2 of 3 planned runs have no "
                             "result, the campaign did not run to its end.</p>"),
      std::string::npos);

  c.planned_runs = 1; // the same run, complete: clean
  finalize(c);
  EXPECT_EQ(hilrig::test::count_of(to_junit_xml(c), "<error "), 0U);
  EXPECT_EQ(to_report_html(c).find("Verdict error: "), std::string::npos);
}

// A suite in which one campaign has no results at all (a rig fault before it ran, a stop
// before it started) exits 3; its junit.xml must not read green either: that campaign is a
// testsuite of one erroring testcase, in the root's counts too.
TEST(Junit, ASuiteCampaignWithoutResultsIsAnError) {
  CampaignResult c = junit_campaign(10.0, 1);
  finalize(c);
  ASSERT_EQ(c.verdict, Outcome::Pass);
  JunitCampaign none;
  none.file = "dir/locked.toml";
  none.no_result = "no results: rig fault (see the command's messages)";
  const std::vector<JunitCampaign> suite = {{&c, "x.toml", {}, runs_of(c), nullptr, {}}, none}; // 2 + 1 tests
  const std::string s = to_junit_suite_xml("nightly", suite);
  EXPECT_NE(s.find("<testsuites name=\"nightly\" tests=\"3\" failures=\"0\" errors=\"1\""), std::string::npos)
      << s;
  EXPECT_NE(s.find("<testsuite name=\"locked\" tests=\"1\" failures=\"0\" errors=\"1\""), std::string::npos)
      << s;
  EXPECT_NE(s.find("<error message=\"no results: rig fault (see the command&#39;s messages)\""),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("<property name=\"campaign_file\" value=\"dir/locked.toml\"/>"), std::string::npos) << s;
  EXPECT_EQ(hilrig::test::count_of(s, "<testsuite "), 2U);
  // Its [campaign] name when known (a campaign the suite's stop kept from starting): the
  // testsuite and classname its results would have had, so CI keeps one history.
  none.campaign = "locked-campaign";
  const std::string named =
      to_junit_suite_xml("nightly", {{&c, "x.toml", {}, runs_of(c), nullptr, {}}, none});
  EXPECT_NE(named.find("<testsuite name=\"locked-campaign\" tests=\"1\""), std::string::npos) << named;
  EXPECT_NE(named.find("classname=\"locked-campaign.campaign\""), std::string::npos) << named;
}

TEST(Junit, AFaultCaughtByOneOfItsCheckersHasNoFailure) {
  // Caught by ls1-throughput (it failed); ls1-advance, also a must_catch check, passed: the
  // run passes, so junit.xml must be clean (it agrees with the exit status, 0).
  CampaignResult c;
  c.campaign = "x";
  c.planned_runs = 2;
  c.runs = {test::fault_run(0, "slow", true), test::fault_run(1, "slow", false)};
  for (auto& run : c.runs) run.must_catch = {"ls1-throughput", "ls1-advance"};
  finalize(c);
  ASSERT_EQ(run_outcome(c.runs[0]), Outcome::Pass);
  const std::string x = to_junit_xml(c);
  // Run 1 missed it: both of its must_catch checks passed, both are failures.
  EXPECT_EQ(hilrig::test::count_of(x, "<failure "), 2U);
  EXPECT_EQ(hilrig::test::count_of(x, "<testsuite name=\"x.ls1/run0\" tests=\"2\" failures=\"0\""), 1U) << x;
}

TEST(Junit, RigErrorIsAnErrorTestcase) {
  CampaignResult c;
  c.campaign = "x";
  c.planned_runs = 1;
  c.runs = {test::nominal_run(0, 10.0)};
  c.runs[0].error = "CAN bus-off";
  finalize(c);
  const std::string x = to_junit_xml(c);
  EXPECT_EQ(hilrig::test::count_of(x, "<error "), 1U);
  EXPECT_NE(x.find("<testcase name=\"rig\""), std::string::npos);
}

// Times come from the wall clock of the run that made them (JunitClock::run_seconds): each
// testcase an equal share of its run's, adding up. A run whose wall time is not known (a
// merge of results.json, which holds none) writes no time, nor does any element holding it:
// never a 0 that reads as a run that took no time.
TEST(Junit, TimesAreTheRunsWallTimeOrAbsentWhenNotKnown) {
  CampaignResult c = test::sample_campaign(3); // runs 0, 1 nominal, run 2 a fault run: 2 cases each
  JunitClock clock;
  clock.run_seconds = {{0, 0.5}, {1, 0.25}, {2, 1.5}};
  std::string x = to_junit_xml(c, clock);
  EXPECT_EQ(hilrig::test::count_of(x, "<testcase "), 6U);
  EXPECT_EQ(hilrig::test::count_of(x, "classname=\"ans1-sample.ls1/run0\" time=\"0.250\""), 2U) << x;
  EXPECT_EQ(hilrig::test::count_of(x, "classname=\"ans1-sample.ls1/run1\" time=\"0.125\""), 2U) << x;
  EXPECT_EQ(hilrig::test::count_of(x, "classname=\"ans1-sample.ls1/run2\" time=\"0.750\""), 2U) << x;
  EXPECT_NE(x.find("errors=\"0\" time=\"2.250\">"), std::string::npos) << x; // testsuites: the sum
  clock.run_seconds.erase(1);
  x = to_junit_xml(c, clock);
  EXPECT_EQ(hilrig::test::count_of(x, "classname=\"ans1-sample.ls1/run0\" time=\"0.250\""), 2U) << x;
  EXPECT_EQ(hilrig::test::count_of(x, "classname=\"ans1-sample.ls1/run1\">"), 2U) << x; // no time
  EXPECT_EQ(hilrig::test::count_of(x, "<testsuite "), 3U);
  EXPECT_EQ(hilrig::test::count_of(x, " time=\""), 6U)
      << x; // runs 0 and 2: 4 testcases and their 2 testsuites
  EXPECT_EQ(hilrig::test::count_of(x, "time=\"0.000\""), 0U) << x;
  x = to_junit_xml(c); // no wall times at all
  EXPECT_EQ(hilrig::test::count_of(x, " time=\""), 0U) << x;
}

// A suite's junit.xml from each campaign's body made beforehand (junit_suite_body, while its runs
// are held) is the text read from the runs when it is written: counts, times and testcases.
TEST(Junit, ASuiteFromBodiesMadeBeforehandIsTheTextFromTheRuns) {
  CampaignResult a = test::sample_campaign(3); // 2 testcases per run: 6
  CampaignResult b;
  b.campaign = "ans1 <sample>";
  b.planned_runs = 2;
  b.runs = {test::nominal_run(0, 21.0), test::fault_run(1, "slow", false)}; // one failure each
  finalize(b);
  JunitClock timed;
  timed.run_seconds = {{0, 0.1}, {1, 0.2}, {2, 0.7}};
  JunitClock partly; // run 1's wall time not known: no time on its campaign nor the suite
  partly.run_seconds = {{0, 0.3}};
  const std::vector<JunitCampaign> from_runs = {{&a, "a.toml", timed, runs_of(a), nullptr, {}},
                                                {&b, "b.toml", partly, runs_of(b), nullptr, {}}};
  const JunitSuiteBody body_a = junit_suite_body(a, runs_of(a), timed);
  const JunitSuiteBody body_b = junit_suite_body(b, runs_of(b), partly);
  EXPECT_EQ(body_a.counts.tests, 6U);
  EXPECT_TRUE(body_a.counts.timed);
  EXPECT_FALSE(body_b.counts.timed);
  EXPECT_EQ(hilrig::test::count_of(body_a.testcases, "<testcase "), 6U);
  std::vector<JunitCampaign> from_bodies = from_runs;
  from_bodies[0].body = &body_a;
  from_bodies[1].body = &body_b;
  const std::string x = to_junit_suite_xml("suite", from_runs);
  EXPECT_EQ(to_junit_suite_xml("suite", from_bodies), x);
  EXPECT_EQ(hilrig::test::count_of(x, "<testsuite "), 2U);
  EXPECT_EQ(hilrig::test::count_of(x, " time=\"1.000\" timestamp="), 1U) << x; // campaign a: 0.1 + 0.2 + 0.7
  // Only one campaign given its body: the same text too.
  from_bodies[1].body = nullptr;
  EXPECT_EQ(to_junit_suite_xml("suite", from_bodies), x);
}

} // namespace
} // namespace hilrig::rig
