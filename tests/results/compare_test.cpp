#include <gtest/gtest.h>

#include "rig/results/compare.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

// One nominal run with throughput max `max_us` (limit 20 us).
CampaignResult one_run(double max_us) {
  CampaignResult c;
  c.campaign = "nightly";
  c.planned_runs = 1;
  c.runs = {test::nominal_run(0, max_us)};
  finalize(c);
  return c;
}

const DriftRow& row(const Comparison& c, const std::string& measurement) {
  for (const auto& r : c.rows) {
    if (r.measurement == measurement) return r;
  }
  ADD_FAILURE() << "no row " << measurement;
  static const DriftRow none;
  return none;
}

TEST(Compare, RelativeDefaultFlagsDriftBeyondAndNotWithin) {
  // Default 5%: 10 -> 10.5 us is exactly 5% (within), 10 -> 10.6 us is 6% (beyond).
  const CampaignResult base = one_run(10.0);
  auto c = compare_results(base, one_run(10.5), {});
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::Within);
  EXPECT_FALSE(c.regression());
  c = compare_results(base, one_run(10.6), {});
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::Beyond);
  EXPECT_TRUE(c.regression());
  EXPECT_EQ(c.regressions(), 1U);
  EXPECT_EQ(row(c, "ls1-advance.edge0").drift, Drift::Same);
}

TEST(Compare, NamedAbsoluteThresholdBySuffixLongestMatchWins) {
  // "max=1" (absolute 1 us) accepts 10 -> 11; "ls1-throughput.max=0.5" is longer and wins.
  CompareOptions o;
  o.thresholds = {parse_threshold("max=1")};
  EXPECT_FALSE(compare_results(one_run(10.0), one_run(11.0), o).regression());
  o.thresholds.push_back(parse_threshold("ls1-throughput.max=0.5"));
  EXPECT_TRUE(compare_results(one_run(10.0), one_run(11.0), o).regression());
  EXPECT_EQ(row(compare_results(one_run(10.0), one_run(11.0), o), "ls1-throughput.max").threshold.name,
            "ls1-throughput.max");
  // Relative with %: 20% of 10 = 2.
  o.thresholds = {parse_threshold("max=20%")};
  EXPECT_FALSE(compare_results(one_run(10.0), one_run(12.0), o).regression());
  EXPECT_TRUE(compare_results(one_run(10.0), one_run(12.5), o).regression());
}

TEST(Compare, NewlyFailingAndDisappearedMeasurementsAreRegressions) {
  CompareOptions loose;
  loose.default_rel = 10.0; // no drift can trip it
  auto c = compare_results(one_run(19.0), one_run(21.0), loose);
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::NewlyFails);
  EXPECT_TRUE(c.regression());
  CampaignResult gone = one_run(10.0);
  gone.runs[0].checks.pop_back(); // the advance check vanished
  finalize(gone);
  c = compare_results(one_run(10.0), gone, loose);
  EXPECT_EQ(row(c, "ls1-advance.edge0").drift, Drift::Missing);
  EXPECT_TRUE(c.regression());
  // The reverse (a measurement added) is reported but not a regression.
  c = compare_results(gone, one_run(10.0), loose);
  EXPECT_EQ(row(c, "ls1-advance.edge0").drift, Drift::Added);
  EXPECT_FALSE(c.regression());
  const std::string table = format_comparison(compare_results(one_run(19.0), one_run(21.0), loose));
  EXPECT_NE(table.find("NEWLY FAILS"), std::string::npos);
  EXPECT_NE(table.find("verdict pass -> fail (worse)"), std::string::npos);
}

// A value 1 ns beyond its limit (20 us) reads beyond it, with the limits it broke: "20 NEWLY
// FAILS" beside a 20 us limit would read as a board failed at its limit. At the limit itself the
// value passes and is no regression (the one inclusive rule).
TEST(Compare, ANewlyFailingValueReadsApartFromTheLimitItBroke) {
  CompareOptions loose;
  loose.default_rel = 10.0;
  const std::string table = format_comparison(compare_results(one_run(19.0), one_run(20.001), loose));
  EXPECT_NE(table.find(" 20.001 "), std::string::npos) << table;
  EXPECT_NE(table.find("NEWLY FAILS (us; limits [- .. 20])"), std::string::npos) << table;
  const std::string nano = format_comparison(compare_results(one_run(19.0), one_run(20.000001), loose));
  EXPECT_NE(nano.find(" 20.000001 "), std::string::npos) << nano;
  const Comparison at = compare_results(one_run(19.0), one_run(20.0), loose);
  EXPECT_EQ(row(at, "ls1-throughput.max").drift, Drift::Within);
  EXPECT_EQ(format_comparison(at).find("limits"), std::string::npos);
}

TEST(Compare, RepeatedRunNamesAreComparedOccurrenceByOccurrence) {
  // Two runs both named "ls1/run0" (a repeated point); only the second drifts (10 -> 12 us).
  const auto two = [](double second_max) {
    CampaignResult c;
    c.planned_runs = 2;
    c.runs = {test::nominal_run(0, 10.0), test::nominal_run(1, second_max)};
    c.runs[1].name = c.runs[0].name;
    finalize(c);
    return c;
  };
  const auto c = compare_results(two(10.0), two(12.0), {});
  ASSERT_EQ(c.regressions(), 1U);
  for (const auto& r : c.rows) {
    if (r.regression()) {
      EXPECT_EQ(r.run, "ls1/run0#2");
    }
  }
}

TEST(Compare, MalformedThresholdsAreRejected) {
  EXPECT_THROW((void)parse_threshold("max"), std::invalid_argument);
  EXPECT_THROW((void)parse_threshold("=3"), std::invalid_argument);
  EXPECT_THROW((void)parse_threshold("max=abc"), std::invalid_argument);
  EXPECT_THROW((void)parse_threshold("max=-1"), std::invalid_argument);
  // Not a number or not finite: a NaN threshold judged every drift within it (exit 0), though
  // --default-rel refuses nan and inf.
  EXPECT_THROW((void)parse_threshold("max=nan"), std::invalid_argument);
  EXPECT_THROW((void)parse_threshold("max=inf%"), std::invalid_argument);
  EXPECT_THROW((void)parse_threshold("max=-nan"), std::invalid_argument);
  const Threshold t = parse_threshold("p99=2.5%");
  EXPECT_EQ(t.name, "p99");
  EXPECT_TRUE(t.relative);
  EXPECT_DOUBLE_EQ(t.value, 0.025);
}

// A fault run ("late") that both checks may catch (docs/campaigns.md, judgement table: a failing
// caught_by check reads "caught"): the throughput max is 35 us (over 20: caught) or 15 us, the
// advance edge 97 counts (beyond [93, 95]: caught) or 94.
CampaignResult fault_campaign(bool throughput_catches, bool advance_catches) {
  CampaignResult c;
  c.campaign = "nightly";
  c.planned_runs = 1;
  RunResult run = test::fault_run(0, "late", throughput_catches);
  run.name = "fault late";
  run.must_catch = {"ls1-throughput", "ls1-advance"};
  if (advance_catches) {
    Measurement& edge = run.checks[1].measurements[0];
    edge.value = 97.0;
    edge.outcome = judge(edge.value, edge.lower, edge.upper);
  }
  c.runs = {run};
  finalize(c);
  return c;
}

// docs/campaigns.md "hilrig compare": in a fault run a check that now catches the fault is an
// improvement, never "NEWLY FAILS" (its failing measurement is the fault's evidence).
TEST(CompareFaultRuns, ACheckThatNowAlsoCatchesIsAnImprovement) {
  CompareOptions loose;
  loose.default_rel = 10.0; // only the words decide
  const Comparison c = compare_results(fault_campaign(true, false), fault_campaign(true, true), loose);
  EXPECT_EQ(row(c, "ls1-advance.edge0").drift, Drift::NowCatches);
  EXPECT_EQ(row(c, "ls1-advance.edge0").now_word, Judgement::Caught);
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::Same); // still caught, same value
  EXPECT_FALSE(c.regression());
  EXPECT_EQ(c.improvements(), 1U);
  const std::string table = format_comparison(c);
  EXPECT_EQ(table.find("NEWLY FAILS"), std::string::npos) << table;
  EXPECT_NE(table.find("now catches"), std::string::npos) << table;
  EXPECT_NE(table.find("0 regressions, 1 improvements; verdict pass -> pass"), std::string::npos) << table;
}

// The reverse: the advance check stops catching while throughput still catches. The fault is
// still caught (verdict pass), but detection was lost: a regression.
TEST(CompareFaultRuns, ACheckThatStopsCatchingIsARegressionThoughTheFaultIsStillCaught) {
  CompareOptions loose;
  loose.default_rel = 10.0;
  const Comparison c = compare_results(fault_campaign(true, true), fault_campaign(true, false), loose);
  EXPECT_EQ(row(c, "ls1-advance.edge0").drift, Drift::NoLongerCatches);
  EXPECT_TRUE(c.regression());
  EXPECT_EQ(c.regressions(), 1U);
  EXPECT_EQ(c.now_verdict, Outcome::Pass);
  EXPECT_NE(format_comparison(c).find("NO LONGER CATCHES"), std::string::npos);
}

// A fault no check catches any more: the catching check reads "fail" (the fault went
// unnoticed), its measurement passes; the row is NO LONGER CATCHES and the verdict is worse.
// Back again (not caught -> caught): an improvement, verdict better, exit 0.
TEST(CompareFaultRuns, AFaultNoLongerCaughtIsARegressionAndCaughtAgainAnImprovement) {
  CompareOptions loose;
  loose.default_rel = 10.0;
  Comparison c = compare_results(fault_campaign(true, false), fault_campaign(false, false), loose);
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::NoLongerCatches);
  EXPECT_EQ(row(c, "ls1-throughput.max").now_word, Judgement::Pass);
  EXPECT_TRUE(c.regression());
  EXPECT_NE(format_comparison(c).find("verdict pass -> fail (worse)"), std::string::npos);
  c = compare_results(fault_campaign(false, false), fault_campaign(true, false), loose);
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::NowCatches);
  EXPECT_FALSE(c.regression());
  EXPECT_NE(format_comparison(c).find("verdict fail -> pass (better)"), std::string::npos);
}

// A nominal run that failed and now passes is an improvement even when its value moved far
// beyond any threshold (21 -> 10 us against a 20 us limit); pass -> fail stays NEWLY FAILS.
TEST(CompareFaultRuns, ANominalFailThatNowPassesIsAnImprovement) {
  const Comparison c = compare_results(one_run(21.0), one_run(10.0), {});
  EXPECT_EQ(row(c, "ls1-throughput.max").drift, Drift::NowPasses);
  EXPECT_FALSE(c.regression());
  EXPECT_EQ(c.improvements(), 1U);
  EXPECT_EQ(row(compare_results(one_run(10.0), one_run(21.0), {}), "ls1-throughput.max").drift,
            Drift::NewlyFails);
}

// docs/campaigns.md "hilrig compare": only a drift strictly beyond its threshold counts, by
// the checks' one comparison rule (judge()). 18.8813 -> 19.825365 is exactly +5 % (in
// doubles 0.944065 / 18.8813 = 0.05000000000000011, which a plain ">" flagged): at the
// threshold within, a hair inside within, a hair beyond flagged, both ways; likewise an
// absolute threshold of 2 at 2, 1.999 and 2.001.
TEST(Compare, ADriftExactlyAtItsThresholdIsWithin) {
  const auto at = [](double base, double now, const char* threshold) {
    CompareOptions o;
    o.thresholds = {parse_threshold(threshold)};
    return row(compare_results(one_run(base), one_run(now), o), "ls1-throughput.max").drift;
  };
  EXPECT_EQ(at(18.8813, 19.825365, "max=5%"), Drift::Within);
  EXPECT_EQ(at(18.8813, 19.825364, "max=5%"), Drift::Within);
  EXPECT_EQ(at(18.8813, 19.825366, "max=5%"), Drift::Beyond);
  EXPECT_EQ(at(18.8813, 17.937235, "max=5%"), Drift::Within);
  EXPECT_EQ(at(18.8813, 17.937234, "max=5%"), Drift::Beyond);
  EXPECT_EQ(at(10.0, 12.0, "max=2"), Drift::Within);
  EXPECT_EQ(at(10.0, 11.999, "max=2"), Drift::Within);
  EXPECT_EQ(at(10.0, 12.001, "max=2"), Drift::Beyond);
}

} // namespace
} // namespace hilrig::rig
