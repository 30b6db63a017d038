#include "rig/cli/run_command.hpp"

#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "core/trace.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"

namespace hilrig::cli {

namespace {

constexpr std::size_t kMaxFailureTraces = 20;

void write_trace_files(const std::filesystem::path& dir, const std::string& stem,
                       const TraceRecorder& trace) {
  std::ofstream vcd(dir / (stem + ".vcd"), std::ios::binary);
  write_vcd(trace, vcd);
  if (!vcd) throw campaign::RigFault("cannot write " + (dir / (stem + ".vcd")).string());
}

} // namespace

std::optional<std::pair<std::size_t, std::size_t>> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  std::size_t k = 0;
  std::size_t n = 0;
  const char* b = text.data();
  const auto r1 = std::from_chars(b, b + slash, k);
  const auto r2 = std::from_chars(b + slash + 1, b + text.size(), n);
  if (r1.ec != std::errc{} || r1.ptr != b + slash || r2.ec != std::errc{} || r2.ptr != b + text.size())
    return std::nullopt;
  if (n == 0 || k >= n) return std::nullopt;
  return std::make_pair(k, n);
}

int run_campaign(const RunOptions& o, std::ostream& err) {
  const auto shard = parse_shard(o.shard);
  if (!shard) {
    err << fmt::format("hilrig run: --shard {}: expected K/N with 0 <= K < N (e.g. 0/4)\n", o.shard);
    return kBadInput;
  }
  campaign::Campaign c;
  try {
    c = campaign::load_campaign(o.file);
  } catch (const campaign::CampaignError& e) {
    err << e.what() << '\n';
    return kBadInput;
  }
  const std::uint64_t seed = o.seed.value_or(c.seed);
  c.runs = campaign::plan_runs(c, seed);
  const std::vector<campaign::RunSpec> runs = campaign::shard(c.runs, shard->first, shard->second);

  try {
    std::filesystem::create_directories(o.out);
    const campaign::Executive exec(c);
    bool can_used = false;
    std::size_t failure_traces = 0;
    std::ofstream can_log;
    const auto progress = [&](std::size_t done, std::size_t total, const campaign::RunSpec& run) {
      if (!o.progress) return;
      err << fmt::format("\r[{}/{}] run {} {}\x1b[K", done + 1, total, run.index, run.label) << std::flush;
    };
    const auto sink = [&](const campaign::RunSpec& run, const campaign::RunOutput& out) {
      if (!out.trace) return;
      if (&run == &runs.front()) write_trace_files(o.out, "trace", *out.trace);
      if (rig::run_outcome(out.result) != rig::Outcome::Pass && failure_traces < kMaxFailureTraces) {
        ++failure_traces;
        write_trace_files(o.out, fmt::format("trace-run{}", run.index), *out.trace);
      }
      if (!out.trace->can_frames().empty()) {
        if (!can_used) can_log.open(o.out / "can.log", std::ios::binary);
        can_used = true;
        // Virtual time starts at 0, and log2asc takes a frame at second 0 for the start of a new
        // log: stamp frames as virtual time after a fixed epoch (2000-01-01T00:00:00Z), which
        // keeps the log deterministic and readable by can-utils.
        CandumpOptions options;
        options.epoch = seconds(946'684'800);
        write_candump(*out.trace, can_log, options);
      }
    };
    rig::CampaignResult result = exec.run_all(
        runs, seed,
        rig::Shard{static_cast<std::uint32_t>(shard->first), static_cast<std::uint32_t>(shard->second)},
        progress, sink);
    if (o.progress) err << '\n';
    rig::write_results_file(o.out / "results.json", result);
    rig::write_file_atomically(o.out / "junit.xml", rig::to_junit_xml(result));
    rig::write_file_atomically(o.out / "report.html", rig::to_report_html(result));

    const auto& t = result.totals;
    err << fmt::format("{}: {} run(s), {} passed, {} failed, {} errored; faults caught {}/{}; verdict {}\n",
                       c.name, t.runs, t.runs_passed, t.runs_failed, t.runs_errored, t.faults_caught,
                       t.faults, rig::to_string(result.verdict));
    for (const auto& run : result.runs)
      if (!run.error.empty())
        err << fmt::format("run {} ({}): rig fault: {}\n", run.index, run.name, run.error);
    for (const auto& run : result.runs)
      if (!run.error.empty()) return kRigFault;
    return result.verdict == rig::Outcome::Pass ? kPassed : kCheckFailed;
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    return kRigFault;
  }
}

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "run a campaign file and write its results");
  cmd->add_option("file", options->file, "the campaign file (.toml)")->required();
  cmd->add_option("--out", options->out, "directory for results.json, junit.xml, report.html, trace.vcd")
      ->required();
  cmd->add_option("--seed", options->seed, "base seed (overrides [campaign] seed)");
  cmd->add_option("--shard", options->shard, "K/N: run only the runs whose index mod N is K (0-based)");
  cmd->callback([options] {
    options->progress = isatty(fileno(stderr)) != 0;
    const int status = run_campaign(*options, std::cerr);
    if (status != kPassed) exit_with(status);
  });
}

} // namespace hilrig::cli
