#pragma once
// A small hand-made campaign result for the results tests: nominal runs, a fault caught, a
// fault missed, series for a histogram and windows for timing diagrams.

#include <cstddef>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig::test {

// One nominal run (index i) whose throughput max is `max_us` against a 20 us limit, and whose
// advance edge is at 94 counts against [93, 95].
RunResult nominal_run(std::uint64_t index, double max_us);
// A fault run: `fault` injected, must be caught by "ls1-throughput"; `caught` chooses
// whether the throughput check failed.
RunResult fault_run(std::uint64_t index, const std::string& fault, bool caught);

// Runs 0..n-1: every third run (index % 3 == 2) is a fault run ("slow_output", caught),
// the others nominal with max = 10 + index us. Finalized, planned_runs = n.
CampaignResult sample_campaign(std::size_t n);

} // namespace hilrig::rig::test
