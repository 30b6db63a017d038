#include <gtest/gtest.h>

#include <regex>

#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/svg.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

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
  EXPECT_EQ(count_of(x, "<testcase "), 10U);
  EXPECT_EQ(count_of(x, "<testsuite "), 5U);
  EXPECT_EQ(count_of(x, "<failure "), 2U);
  EXPECT_EQ(count_of(x, "<skipped "), 2U);
  EXPECT_NE(x.find("<testsuites name=\"ans1 &lt;sample&gt;\" tests=\"10\" failures=\"2\" errors=\"0\""),
            std::string::npos);
  EXPECT_NE(x.find("fault &#39;slow&#39; not caught"), std::string::npos);
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
  EXPECT_EQ(count_of(x, "<failure "), 2U);
  EXPECT_EQ(count_of(x, "<testsuite name=\"x.ls1/run0\" tests=\"2\" failures=\"0\""), 1U) << x;
}

TEST(Junit, RigErrorIsAnErrorTestcase) {
  CampaignResult c;
  c.campaign = "x";
  c.planned_runs = 1;
  c.runs = {test::nominal_run(0, 10.0)};
  c.runs[0].error = "CAN bus-off";
  finalize(c);
  const std::string x = to_junit_xml(c);
  EXPECT_EQ(count_of(x, "<error "), 1U);
  EXPECT_NE(x.find("<testcase name=\"rig\""), std::string::npos);
}

TEST(Report, SelfContainedWithVerdictTablesDiagramsAndHistograms) {
  const CampaignResult c = test::sample_campaign(3);
  const std::string html = to_report_html(c);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0U);
  EXPECT_NE(html.find("Verdict: <span class=\"pass\">pass</span>"), std::string::npos);
  // 3 runs: one advance timing diagram and one latency histogram each.
  EXPECT_EQ(count_of(html, "<svg "), 6U);
  EXPECT_EQ(count_of(html, "expected window (green) against captured edge"), 3U);
  EXPECT_EQ(count_of(html, "latency histogram"), 3U);
  EXPECT_NE(html.find("Fault detection"), std::string::npos);
  // Nothing fetched from elsewhere.
  for (const char* external : {"src=", "href=", "<link", "<script", "@import", "url("}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
}

TEST(Svg, TimingDiagramPlacesTheEdgeInsideTheWindowBand) {
  // Window 0..2 us, edge at 1 us: margin max(25% of 2 us, 1 us) = 1 us, so the axis spans
  // -1..3 us over 500 px from x = 10: band from 135 to 385, edge at 260.
  Measurement m;
  m.name = "a.edge0";
  m.window = TraceWindow{Nanos{0}, Nanos{2000}};
  m.at = Nanos{1000};
  m.outcome = Outcome::Pass;
  const std::string svg = timing_diagram_svg(m, Judgement::Pass);
  EXPECT_NE(svg.find("<rect x=\"135.0\" y=\"12\" width=\"250.0\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("x1=\"260.0\""), std::string::npos) << svg;
  m.at.reset();
  EXPECT_TRUE(timing_diagram_svg(m, Judgement::Pass).empty());
}

TEST(Svg, HistogramBinsWorkedByHand) {
  // 4 values -> ceil(sqrt(4)) = 2 bins over [1, 4]: {1, 2} in the first, {3, 4} in the second
  // (4 is the top edge, clamped into the last bin). Both bars full height (100 px).
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0};
  const std::string svg = histogram_svg(v, "us", std::nullopt);
  EXPECT_EQ(count_of(svg, "height=\"100.0\""), 2U) << svg;
  EXPECT_NE(svg.find("4 samples, peak bin 2"), std::string::npos);
  EXPECT_NE(histogram_svg(v, "us", 5.0).find("limit 5 us"), std::string::npos);
}

} // namespace
} // namespace hilrig::rig
