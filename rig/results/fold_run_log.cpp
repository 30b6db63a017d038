#include "rig/results/fold_run_log.hpp"

#include <ostream>

#include "rig/results/atomic_file.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::rig {

CampaignResult fold_run_log(const std::filesystem::path& log, const std::filesystem::path& dir,
                            const CampaignResult& facts, const JunitClock& clock) {
  CampaignResult result = read_run_log_summary(log, facts.interrupted);
  result.started_at = facts.started_at;
  result.host = facts.host;
  const RunSource runs = run_log_runs(log);
  write_results_file(dir / "results.json", result, runs);
  write_file_atomically(dir / "junit.xml",
                        [&](std::ostream& out) { write_junit_xml(result, runs, clock, sink_to(out)); });
  write_file_atomically(dir / "report.html",
                        [&](std::ostream& out) { write_report_html(result, runs, sink_to(out)); });
  return result;
}

} // namespace hilrig::rig
