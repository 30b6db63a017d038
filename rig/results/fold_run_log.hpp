#pragma once
// The end of a campaign: its run log (rig/results/run_log.hpp) folded into results.json,
// junit.xml and report.html without holding its runs.

#include <filesystem>

#include "rig/results/campaign_result.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::rig {

// Writes results.json, junit.xml and report.html into dir from the run log at `log`, each
// reading the log a record at a time (a few passes: totals first, then the text), so the
// memory the fold holds does not grow with the runs and its time is linear in them. `facts`
// gives what the log does not hold: the stop the campaign ended with and the wall clock
// (interrupted, started_at, host); its runs are not used. Returns the campaign without its runs.
[[nodiscard]] CampaignResult fold_run_log(const std::filesystem::path& log, const std::filesystem::path& dir,
                                          const CampaignResult& facts, const JunitClock& clock);
// The same files from the writer of the log: its summary and its runs (RunLog::summary,
// RunLog::runs), held in memory while they fit its budget, else read back from the file.
[[nodiscard]] CampaignResult fold_run_log(const RunLog& log, const std::filesystem::path& dir,
                                          const CampaignResult& facts, const JunitClock& clock);

} // namespace hilrig::rig
