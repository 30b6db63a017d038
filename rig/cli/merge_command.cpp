#include "rig/cli/merge_command.hpp"

#include <algorithm>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/cli/directory_lock.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/run_evidence.hpp"
#include "rig/cli/same_file.hpp"
#include "rig/results/atomic_file.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/merge.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::cli {
namespace {

struct MergeArgs {
  std::string out;
  std::vector<std::string> shards;
};

namespace fs = std::filesystem;

// junit.xml and report.html beside the merged results: "results.json" -> "junit.xml" and
// "report.html" (the layout of `hilrig run --out`), any other "NAME.json" -> "NAME.junit.xml"
// and "NAME.report.html" (so a merge written into a shard's directory keeps the shard's own).
fs::path beside(const fs::path& out, const char* file) {
  if (out.filename() == "results.json") return out.parent_path() / file;
  return out.parent_path() / (out.stem().string() + "." + file);
}

// A merge whose output (or the junit.xml or report.html beside it) is one of its inputs would
// replace a shard's evidence with the merged result, and one written under the name of a file
// `hilrig run` writes (trace.vcd, junit.xml, runs.jsonl, ...) into the directory of a run whose
// results.json or runs.jsonl is an input would replace that run's own evidence (a trace the
// merged result links to): both refused before anything is read. Another name there
// (merged.json, merged.junit.xml) keeps the run's files. Folding one run's own log into its
// results.json, junit.xml and report.html, `hilrig merge OUT/results.json OUT/runs.jsonl`, is the
// kill recovery (docs/campaigns.md) and stays.
void refuse_overwriting_an_input(const MergeArgs& a) {
  const fs::path out(a.out);
  const std::vector<fs::path> written{out, beside(out, "junit.xml"), beside(out, "report.html")};
  const bool kill_recovery = a.shards.size() == 1 && fs::path(a.shards.front()).extension() == ".jsonl";
  const auto directory = [](const fs::path& p) {
    return p.parent_path().empty() ? fs::path(".") : p.parent_path();
  };
  for (const std::string& input : a.shards) {
    const fs::path in(input);
    const bool a_runs_own = in.filename() == "results.json" || in.filename() == rig::kRunLogName;
    for (const fs::path& w : written) {
      if (same_file(w, in))
        throw std::invalid_argument(
            fmt::format("{} is also an input ({}): the merge would overwrite it; write "
                        "the merge elsewhere (e.g. merged.json)",
                        w.string(), input));
      const std::string name = w.filename().string();
      const bool folded_back = kill_recovery && (w != out || name == "results.json");
      if (a_runs_own && is_run_evidence(name) && !folded_back && same_file(directory(w), directory(in)))
        throw std::invalid_argument(
            fmt::format("{} is the run's own file beside the input {}: the merge would "
                        "overwrite it; write the merge elsewhere (e.g. merged.json)",
                        w.string(), input));
    }
  }
}

// The directory the merge writes into, made when missing, and taken as `hilrig run --out`
// takes its own: a run still writing there (its .hilrig.lock held) is not overwritten (the
// kill-recovery merge `hilrig merge OUT/results.json OUT/runs.jsonl` writes into the run's own
// directory). Held until the merge's files are written.
class MergeTarget {
public:
  explicit MergeTarget(const fs::path& out) {
    const fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!lock_.take(dir, DirectoryLock::Missing::HoldNothing))
      throw Busy(
          fmt::format("{} is being written by a hilrig run (its .hilrig.lock is held): merge when it ends",
                      dir.string()));
  }
  struct Busy : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

private:
  DirectoryLock lock_;
};

// A run's trace is named relative to its shard's results.json; the merged files link it from
// where they are.
void relink_traces(rig::CampaignResult& shard, const fs::path& shard_file, const fs::path& out) {
  const fs::path from = fs::absolute(out).parent_path();
  for (rig::RunResult& run : shard.runs) {
    if (run.trace.empty()) continue;
    const fs::path trace = fs::absolute(shard_file).parent_path() / run.trace;
    const fs::path relative = trace.lexically_relative(from);
    run.trace = (relative.empty() ? trace : relative).generic_string();
  }
}

int run_merge(const MergeArgs& a) {
  int status = kPassed;
  try {
    refuse_overwriting_an_input(a);
    std::vector<rig::CampaignResult> shards;
    for (const auto& path : a.shards) {
      shards.push_back(rig::read_results_file(path));
      relink_traces(shards.back(), path, a.out);
    }
    const rig::CampaignResult merged = rig::merge_shards(std::move(shards), a.shards);
    const MergeTarget target(a.out);
    // The wall-clock facts the shards kept: the first shard's start and host. Each run's wall
    // time is not in results.json: the testcases carry no time (rig/results/junit.hpp).
    rig::JunitClock clock;
    if (merged.started_at) clock.started_at = *merged.started_at;
    if (merged.host) clock.hostname = *merged.host;
    const fs::path junit = beside(a.out, "junit.xml");
    const fs::path report = beside(a.out, "report.html");
    // Every text is made before the first is written: a result that cannot be written whole
    // (a figure that throws) leaves no merged results.json without its junit.xml.
    const std::string results_text = rig::to_json_text(merged);
    const std::string junit_text = rig::to_junit_xml(merged, clock);
    const std::string report_text = rig::to_report_html(merged);
    try {
      rig::write_file_atomically(a.out, results_text);
      rig::write_file_atomically(junit, junit_text);
      rig::write_file_atomically(report, report_text);
    } catch (const std::exception& e) {
      throw WriteFailed(e.what());
    }
    std::fputs(fmt::format("merged {} shards: {} runs, verdict {}; wrote {}, {}, {}\n", a.shards.size(),
                           merged.runs.size(), rig::to_string(merged.verdict), a.out, junit.string(),
                           report.string())
                   .c_str(),
               stdout);
    // The merged verdict is the CI job's, as `hilrig run`'s exit status is the unsharded run's:
    // a merge step judges the campaign with no glue. A shard stopped by a signal, or a run a rig
    // fault stopped, is the rig's failure, 3, as `hilrig run` exits for it: not the board's, 1.
    // Fewer runs than planned (the run log of a killed run, a results.json a run wrote before
    // its end) is incomplete evidence as an interrupted shard is: 3, whichever file it came in.
    if (merged.runs.size() < merged.planned_runs)
      std::fputs(fmt::format("hilrig merge: incomplete evidence: {} of the {} planned runs (a run stopped or "
                             "killed before its end)\n",
                             merged.runs.size(), merged.planned_runs)
                     .c_str(),
                 stderr);
    const bool rig_fault = !merged.complete || // fewer runs than planned, or a shard interrupted
                           std::any_of(merged.runs.begin(), merged.runs.end(),
                                       [](const rig::RunResult& run) { return !run.error.empty(); });
    if (rig_fault)
      status = kRigFault;
    else if (merged.verdict != rig::Outcome::Pass)
      status = kCheckFailed;
  } catch (const WriteFailed& e) {
    std::fprintf(stderr, "hilrig merge: %s\n", e.what());
    return kRigFault;
  } catch (const MergeTarget::Busy& e) {
    std::fprintf(stderr, "hilrig merge: %s\n", e.what());
    return kRigFault; // as `hilrig run` on a directory in use: the rig cannot do it now
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hilrig merge: %s\n", e.what());
    return kBadInput;
  }
  return status;
}

} // namespace

void add_merge_command(CLI::App& app) {
  auto args = std::make_shared<MergeArgs>();
  auto* cmd = app.add_subcommand(
      "merge",
      "merge the results.json of every shard into one, with its junit.xml and report.html; exit 0 when the "
      "merged verdict is pass, 1 when not, 2 on bad input, 3 on a rig fault or incomplete evidence");
  cmd->add_option("out", args->out,
                  "the merged results.json to write; junit.xml and report.html go beside it (NAME.json: "
                  "NAME.junit.xml, NAME.report.html)")
      ->required();
  cmd->add_option("shards", args->shards, "one results.json per shard")->required();
  cmd->callback([args] {
    const int code = run_merge(*args);
    if (code != kPassed) exit_with(code);
  });
}

} // namespace hilrig::cli
