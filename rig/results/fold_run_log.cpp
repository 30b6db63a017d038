#include "rig/results/fold_run_log.hpp"

#include <ostream>

#include "rig/results/atomic_file.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::rig {

namespace {

CampaignResult write_folded(CampaignResult result, const RunSource& runs, const RunDumpSource& dumps,
                            const std::filesystem::path& dir, const CampaignResult& facts,
                            const JunitClock& clock) {
  result.started_at = facts.started_at;
  result.host = facts.host;
  write_results_dumps(dir / "results.json", result, dumps);
  write_file_atomically(dir / "junit.xml",
                        [&](std::ostream& out) { write_junit_xml(result, runs, clock, sink_to(out)); });
  write_file_atomically(dir / "report.html",
                        [&](std::ostream& out) { write_report_html(result, runs, sink_to(out)); });
  return result;
}

} // namespace

CampaignResult fold_run_log(const std::filesystem::path& log, const std::filesystem::path& dir,
                            const CampaignResult& facts, const JunitClock& clock) {
  const RunSource runs = run_log_runs(log);
  return write_folded(read_run_log_summary(log, facts.interrupted), runs, dumps_of(runs), dir, facts, clock);
}

CampaignResult fold_run_log(const RunLog& log, const std::filesystem::path& dir, const CampaignResult& facts,
                            const JunitClock& clock) {
  return write_folded(log.summary(facts.interrupted), log.runs(), log.run_dumps(), dir, facts, clock);
}

} // namespace hilrig::rig
