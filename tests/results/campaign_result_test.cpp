#include <gtest/gtest.h>

#include "rig/results/campaign_result.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

using test::fault_run;
using test::nominal_run;

TEST(CampaignResult, FaultRunPassesWhenItsMustCatchCheckFails) {
  EXPECT_EQ(run_outcome(fault_run(0, "slow_output", true)), Outcome::Pass);
  EXPECT_TRUE(caught(fault_run(0, "slow_output", true)));
  EXPECT_EQ(run_outcome(fault_run(0, "slow_output", false)), Outcome::Fail);
  EXPECT_EQ(run_outcome(nominal_run(0, 20.0)), Outcome::Pass);
  EXPECT_EQ(run_outcome(nominal_run(0, 21.0)), Outcome::Fail);
  RunResult erred = nominal_run(0, 10.0);
  erred.error = "bus-off";
  EXPECT_EQ(run_outcome(erred), Outcome::Error);
}

TEST(CampaignResult, TotalsMatrixAndVerdictWorkedByHand) {
  CampaignResult c;
  c.campaign = "x";
  c.planned_runs = 4;
  // Given out of order: finalize sorts by index.
  c.runs = {fault_run(3, "glitch", false), nominal_run(0, 10.0), fault_run(1, "slow_output", true),
            fault_run(2, "glitch", true)};
  finalize(c);
  ASSERT_EQ(c.runs.size(), 4U);
  EXPECT_EQ(c.runs[0].index, 0U);
  EXPECT_EQ(c.runs[3].index, 3U);
  // Runs: 0 pass, 1 pass (caught), 2 pass (caught), 3 fail (missed).
  EXPECT_EQ(c.totals.runs_passed, 3U);
  EXPECT_EQ(c.totals.runs_failed, 1U);
  // Checks: 2 per run = 8, counted by their word. Throughput fails in runs 1 and 2 (35 us >
  // 20): it caught the fault there (caught, not fail). In run 3 it passed, so the fault went
  // unnoticed: fail. Every advance check of a fault run is not judged; run 0's two pass.
  EXPECT_EQ(c.totals.checks, 8U);
  EXPECT_EQ(c.totals.checks_passed, 2U);
  EXPECT_EQ(c.totals.checks_failed, 1U);
  EXPECT_EQ(c.totals.checks_caught, 2U);
  EXPECT_EQ(c.totals.checks_not_judged, 3U);
  EXPECT_EQ(c.totals.checks_errored, 0U);
  EXPECT_EQ(c.totals.measurements, 12U); // 3 per run
  // Matrix sorted by fault: glitch in runs 2, 3 caught once -> not caught; slow_output caught.
  ASSERT_EQ(c.faults.size(), 2U);
  EXPECT_EQ(c.faults[0].fault, "glitch");
  EXPECT_EQ(c.faults[0].runs, (std::vector<std::uint64_t>{2, 3}));
  EXPECT_EQ(c.faults[0].caught_runs, 1U);
  EXPECT_FALSE(c.faults[0].caught());
  EXPECT_TRUE(c.faults[1].caught());
  EXPECT_EQ(c.totals.faults_caught, 1U);
  EXPECT_EQ(c.verdict, Outcome::Fail);
  EXPECT_TRUE(c.complete);
}

TEST(CampaignResult, IncompleteResultIsNotAPass) {
  CampaignResult c;
  c.planned_runs = 2;
  c.runs = {nominal_run(0, 10.0)};
  finalize(c);
  EXPECT_FALSE(c.complete);
  EXPECT_EQ(c.verdict, Outcome::Error);
  c.runs.push_back(nominal_run(1, 11.0));
  finalize(c);
  EXPECT_EQ(c.verdict, Outcome::Pass);
}

} // namespace
} // namespace hilrig::rig
