#include "rig/cli/run_command.hpp"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"
#include "core/trace.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/campaign/modbus_host_link.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/heap_policy.hpp"
#include "rig/cli/output_dir.hpp"
#include "rig/cli/run_progress.hpp"
#include "rig/cli/seed_option.hpp"
#include "rig/cli/serve_devices.hpp"
#include "rig/cli/stop_signals.hpp"
#include "rig/cli/suite_files.hpp"
#include "rig/cli/trace_files.hpp"
#include "rig/cli/wall_clock.hpp"
#include "rig/hardware/hardware_backend.hpp"
#include "rig/results/append_file.hpp"
#include "rig/results/atomic_file.hpp"
#include "rig/results/fold_run_log.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"
#include "rig/results/suite_index.hpp"

namespace hilrig::cli {

namespace {

constexpr std::size_t kMaxFailureTraces = 20;

// Host words as Modbus RTU on a pty pair: the DUT adapter's words from where `hilrig serve`
// puts the device's first command and status words (the whole served map for the ANS1, 4501,
// 7361 and SMD23E; the Series 2700 adapter's words are its own, not the block-transfer map).
campaign::HostLinkFactory modbus_rtu_pty_links() {
  return [](duts::Dut& dut, const duts::DutInfo& info) {
    const ServedDevice* served = find_served_device(info.name);
    if (served == nullptr) throw campaign::RigFault("no Modbus register map for " + info.name);
    const HostWordMap& w = served->words;
    return campaign::modbus_rtu_pty_link(dut, campaign::HostRegisters{w.command_base, info.host.output_words,
                                                                      w.status_base, info.host.input_words});
  };
}

// The link --host-link names, or nullopt (with the message on err) when it cannot serve the campaign.
std::optional<campaign::HostLinkFactory> host_link_for(const RunOptions& o, const campaign::Campaign& c,
                                                       std::ostream& err) {
  if (o.host_link_factory) return o.host_link_factory;
  if (o.host_link == campaign::kInProcessLink) return campaign::HostLinkFactory{};
  if (o.host_link != campaign::kModbusRtuPtyLink) {
    err << fmt::format("hilrig run: --host-link {}: expected {} or {}\n", o.host_link,
                       campaign::kInProcessLink, campaign::kModbusRtuPtyLink);
    return std::nullopt;
  }
  for (const campaign::Scenario& s : c.points) {
    if (find_served_device(s.dut.model) == nullptr) {
      err << fmt::format("hilrig run: --host-link {}: {} has no Modbus register map (served devices: {})\n",
                         o.host_link, s.dut.model, served_device_names());
      return std::nullopt;
    }
  }
  return modbus_rtu_pty_links();
}

// --backend, or the campaign's [dut] backend: a hardware run loads the rig config and places
// every scenario on it before anything moves. Returns an exit status (kPassed: go on).
int choose_backend(const RunOptions& o, campaign::Campaign& c, std::optional<hardware::RigConfig>& rig,
                   std::ostream& err) {
  std::string asked;
  for (const campaign::Scenario& s : c.points)
    if (s.dut.backend != "virtual") asked = s.dut.backend;
  const bool on_rig = o.backend == "hardware" || (o.backend.empty() && (!o.rig.empty() || !asked.empty()));
  if (!on_rig) {
    if (!o.rig.empty()) {
      err << "hilrig run: --rig is for --backend hardware\n";
      return kBadInput;
    }
    // --backend virtual: the same campaign file on the virtual bus, whatever it was written for.
    for (campaign::Scenario& s : c.points) s.dut.backend = "virtual";
    for (auto& points : c.fault_points)
      for (campaign::Scenario& s : points) s.dut.backend = "virtual";
    return kPassed;
  }
  // A device fault or a power cycle is the virtual board's: refused before the rig is asked for.
  try {
    hardware::check_virtual_only(c);
  } catch (const campaign::CampaignError& e) {
    err << e.what() << '\n';
    return kBadInput;
  }
  // Hardware asked for (by --backend or by the campaign) without saying which rig: the
  // command line is incomplete, whichever asked, so it is bad input and nothing runs.
  if (o.rig.empty()) {
    if (o.backend == "hardware")
      err << "hilrig run: --backend hardware needs --rig RIG.toml (docs/rig-config.md)\n";
    else
      err << fmt::format("hilrig run: {}: [dut] backend \"{}\" runs on a rig: it needs --rig RIG.toml "
                         "(docs/rig-config.md), or --backend virtual\n",
                         c.file, asked);
    return kBadInput;
  }
  try {
    rig = hardware::load_rig_config(o.rig);
    hardware::check_campaign_on_rig(c, *rig);
  } catch (const campaign::CampaignError& e) {
    err << e.what() << '\n';
    return kBadInput;
  }
  return kPassed;
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

namespace {

// A campaign read, checked, planned and placed on its backend: nothing has run yet.
struct Prepared {
  campaign::Campaign c;
  std::uint64_t seed = 0;
  std::pair<std::size_t, std::size_t> shard{0, 1};
  std::vector<campaign::RunSpec> runs;
  campaign::HostLinkFactory link;
  std::optional<hardware::RigConfig> rig;
};

// --only and --tag: names this campaign does not have are bad input (with the closest names).
// Returns false (message on err) when the selection leaves nothing to run.
bool select(const RunOptions& o, campaign::Campaign& c, bool in_suite, std::ostream& err) {
  if (o.checks.all()) return true;
  bool known = true;
  if (!in_suite) {
    const std::vector<std::string> names = campaign::check_names(c);
    for (const std::string& n : o.checks.only)
      if (std::find(names.begin(), names.end(), n) == names.end()) {
        err << fmt::format("hilrig run: --only {}: {} has no check of this name{}\n", n, c.file,
                           did_you_mean(n, names));
        known = false;
      }
    const std::vector<std::string> tags = campaign::check_tags(c);
    for (const std::string& t : o.checks.tags)
      if (std::find(tags.begin(), tags.end(), t) == tags.end()) {
        err << fmt::format("hilrig run: --tag {}: {} has no check with this tag{}\n", t, c.file,
                           did_you_mean(t, tags));
        known = false;
      }
  }
  // In a suite, a campaign the selection does not touch is left out.
  return known && campaign::select_checks(c, o.checks) > 0;
}

// Everything a run checks before anything moves. Returns an exit status (kPassed: go on).
int prepare(const RunOptions& o, const std::string& file, bool in_suite, Prepared& p, bool& selected,
            std::ostream& err) {
  const auto shard = parse_shard(o.shard);
  if (!shard) {
    err << fmt::format("hilrig run: --shard {}: expected K/N with 0 <= K < N (e.g. 0/4)\n", o.shard);
    return kBadInput;
  }
  p.shard = *shard;
  try {
    p.c = campaign::load_campaign(file);
  } catch (const campaign::CampaignError& e) {
    err << e.what() << '\n';
    return kBadInput;
  }
  selected = select(o, p.c, in_suite, err);
  if (!selected) return in_suite ? kPassed : kBadInput;
  p.seed = o.seed.value_or(p.c.seed);
  p.c.runs = campaign::plan_runs(p.c, p.seed);
  p.runs = campaign::shard(p.c.runs, shard->first, shard->second);
  std::optional<campaign::HostLinkFactory> link = host_link_for(o, p.c, err);
  if (!link) return kBadInput;
  p.link = std::move(*link);
  return choose_backend(o, p.c, p.rig, err);
}

// What a campaign's run leaves for the suite: its result (when one was written), the
// wall-clock facts for junit.xml, and its exit status.
struct Ran {
  int status = kPassed;
  std::optional<rig::CampaignResult> result; // without its runs: they are in its run log
  std::filesystem::path log;
  rig::JunitClock clock;
  std::optional<rig::JunitSuiteBody> junit; // its part of a suite's junit.xml, when made while held
  std::string not_run;                      // why it never started ("" when it did)
};

// Runs a prepared campaign into dir. The summary goes to out, the rest to err.
// In a suite, junit_held counts the bytes of the campaigns' junit text made so far (Ran::junit):
// while the runs are held and that stays within kRunLogHeldBytes, it is made here, not from the
// run log read back when the suite's junit.xml is written.
Ran execute(const RunOptions& o, Prepared& p, const std::filesystem::path& dir, campaign::StopRequest* stop,
            RunProgress& progress, std::ostream& out, std::ostream& err,
            std::atomic<std::size_t>* junit_held = nullptr) {
  Ran ran;
  // The campaign's wall-clock start, to the second (or the --epoch / SOURCE_DATE_EPOCH given):
  // junit.xml's timestamp, results.json's wall_clock.started_at, and can.log's epoch (so the
  // log's times can be read back from it).
  const auto started_at = wall_start(o.epoch);
  ran.clock.started_at = iso8601_utc(started_at);
  ran.clock.hostname = host_name();
  std::optional<OutputDirectory> out_dir;
  try {
    out_dir.emplace(dir);
  } catch (const ForeignOutput& e) {
    err << "hilrig run: " << e.what() << '\n';
    ran.status = kBadInput;
    return ran;
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    ran.status = kRigFault;
    return ran;
  }
  try {
    campaign::Executive exec(p.c, p.rig ? hardware::hardware_backend(*p.rig, p.c.file, o.rig_ports)
                                        : campaign::RunBackend{});
    exec.use_host_link(p.link);
    exec.scan_every_period(o.exact_scan);
    // A real board plays one probe at a time; virtual runs spread a debounce check's phases.
    if (!p.rig)
      exec.probe_threads(o.probe_threads > 0 ? o.probe_threads
                                             : std::max(1U, std::thread::hardware_concurrency()));
    if (stop != nullptr) exec.stop_on(stop);
    std::size_t failure_traces = 0;
    std::optional<rig::AppendFile> can_log; // one block per run: a failed write keeps the runs before
    // can.log's clock: the campaign's wall-clock start plus virtual time, the runs laid end to end
    // (each run's virtual time starts at 0), so the log's times only go forward and candump's
    // readers (log2asc, canplayer) take it as one capture that began when the campaign did.
    Nanos can_log_offset{
        std::chrono::duration_cast<std::chrono::nanoseconds>(started_at.time_since_epoch()).count()};
    std::chrono::steady_clock::time_point run_start;
    const auto started = [&](std::size_t, std::size_t, const campaign::RunSpec& run) {
      progress.started(p.c.name, run);
      run_start = std::chrono::steady_clock::now();
    };
    const campaign::RunSpec* sunk = nullptr; // the run whose evidence the sink wrote last
    const auto sink = [&](const campaign::RunSpec& run, const campaign::RunOutput& output) {
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
      ran.clock.run_seconds[run.index] = wall;
      sunk = &run;
      const Nanos run_epoch = can_log_offset;
      can_log_offset += p.c.scenario_of(run).end;
      if (!output.trace) return std::string();
      // --trace: a run the policy does not keep formats and writes nothing (its recording, which
      // the checks judged from, goes with it).
      const bool passed = rig::run_outcome(output.result) == rig::Outcome::Pass;
      const bool first = &run == &p.runs.front();
      std::string kept; // the trace file the run's result links (its failure trace when it has one)
      // A run that ran to its end: its trace ends there (a run the rig stopped ends where it stopped).
      const std::optional<Nanos> trace_end =
          output.result.error.empty() ? std::optional(p.c.scenario_of(run).end) : std::nullopt;
      if (first && rig::keeps_trace(o.trace, true, passed)) {
        write_trace_files(dir, "trace", *output.trace, output.result, false, trace_end);
        kept = "trace.vcd";
      }
      if (rig::keeps_trace(o.trace, false, passed) && failure_traces < kMaxFailureTraces) {
        ++failure_traces;
        const std::string stem = fmt::format("trace-run{}", run.index);
        if (kept.empty()) {
          write_trace_files(dir, stem, *output.trace, output.result, true, trace_end);
        } else {
          link_trace_files(dir, "trace", stem, *output.trace, output.result); // the same bytes, once
        }
        kept = stem + ".vcd";
      }
      if (!output.trace->can_frames().empty()) {
        CandumpOptions options;
        options.epoch = run_epoch;
        std::ostringstream frames;
        write_candump(*output.trace, frames, options);
        try {
          if (!can_log) can_log.emplace(dir / "can.log", rig::AppendFile::Sync::None);
          can_log->append(frames.str());
        } catch (const std::runtime_error& e) {
          throw campaign::RigFault(e.what()); // "cannot write OUT/can.log: No space left on device"
        }
      }
      return kept;
    };
    const rig::Shard part{static_cast<std::uint32_t>(p.shard.first),
                          static_cast<std::uint32_t>(p.shard.second)};
    // Each run is appended to the run log as it finishes, so a crash or SIGKILL leaves every
    // finished run; the log's writer keeps the runs for the fold below while they fit its
    // budget (rig/results/run_log.hpp), so a campaign's memory stays bounded however long it is.
    rig::CampaignResult header = exec.planned(p.runs, p.seed, part);
    header.station = o.station;
    header.host_link = o.host_link_factory ? "custom" : o.host_link;
    header.backend = p.rig ? "hardware" : "virtual";
    header.trace_policy = o.trace;
    // The wall-clock facts in the log's header too: a log folded after a kill (hilrig merge
    // OUT/results.json OUT/runs.jsonl) keeps when and where the campaign ran (a trend's label).
    header.started_at = ran.clock.started_at;
    header.host = ran.clock.hostname;
    rig::RunLog log(dir / rig::kRunLogName, header);
    // A run is reported finished once its record is in the log (written and synced): a script
    // that stops hilrig on that line, or a kill right after it, finds the run in runs.jsonl.
    const auto record = [&](const rig::RunResult& run) {
      log.append(run);
      if (sunk != nullptr)
        progress.finished(p.c.name, *sunk, rig::run_outcome(run), ran.clock.run_seconds[run.index]);
    };
    const rig::CampaignResult done = exec.run_all(p.runs, p.seed, part, started, sink, record);
    // The fold takes the runs the log holds, or reads it back a record at a time: its memory
    // does not grow with the runs either.
    rig::CampaignResult facts;
    facts.interrupted = done.interrupted;
    facts.started_at = ran.clock.started_at;
    facts.host = ran.clock.hostname;
    rig::CampaignResult result = rig::fold_run_log(log, dir, facts, ran.clock);
    ran.log = log.path();
    if (junit_held != nullptr && log.holds_runs()) {
      rig::JunitSuiteBody body = rig::junit_suite_body(result, log.runs(), ran.clock);
      const std::size_t size = body.testcases.size();
      if (junit_held->fetch_add(size) + size <= rig::kRunLogHeldBytes) ran.junit = std::move(body);
    }

    const auto& t = result.totals;
    out << fmt::format("{}: {} run(s), {} passed, {} failed, {} errored; faults caught {}/{}; verdict {}\n",
                       p.c.name, t.runs, t.runs_passed, t.runs_failed, t.runs_errored, t.faults_caught,
                       t.faults, rig::to_string(result.verdict));
    bool rig_error = false;
    if (t.runs_errored > 0) // a run a rig error stopped reads "error": only then are the runs visited again
      log.runs()([&](const rig::RunResult& run) {
        if (run.error.empty()) return;
        rig_error = true;
        err << fmt::format("run {} ({}): rig fault: {}\n", run.index, run.name, run.error);
      });
    if (result.interrupted) {
      err << interruption_text(result, dir.string()) << '\n';
      ran.status = kRigFault;
    } else if (rig_error) {
      ran.status = kRigFault;
    } else {
      ran.status = result.verdict == rig::Outcome::Pass ? kPassed : kCheckFailed;
    }
    ran.result = std::move(result);
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    ran.status = kRigFault;
  }
  return ran;
}

RunProgress::Mode progress_mode(const RunOptions& o) {
  if (o.progress_lines) return RunProgress::Mode::Lines;
  return o.progress ? RunProgress::Mode::InPlace : RunProgress::Mode::Quiet;
}

// A suite: every campaign read and checked, then run (N at a time) into OUT/<subdir>/, then
// the aggregated junit.xml and index report.html.
int run_suite(const RunOptions& o, std::ostream& out, std::ostream& err) {
  std::vector<SuiteEntry> entries;
  try {
    entries = collect_campaigns(o.files);
  } catch (const std::invalid_argument& e) {
    err << "hilrig run: " << e.what() << '\n';
    return kBadInput;
  }
  // Every campaign is checked before the first one runs: one bad file stops the suite with
  // every bad file listed (each with its first problem), as a single campaign stops before its
  // first run.
  std::vector<std::unique_ptr<Prepared>> prepared;
  std::vector<SuiteEntry> chosen;
  int status = kPassed;
  for (const SuiteEntry& e : entries) {
    auto p = std::make_unique<Prepared>();
    bool selected = true;
    status = worst_status(status, prepare(o, e.file, true, *p, selected, err));
    if (!selected) continue;
    prepared.push_back(std::move(p));
    chosen.push_back(e);
  }
  if (status != kPassed) return status;
  if (prepared.empty()) {
    std::vector<std::string> names;
    for (const SuiteEntry& e : entries) {
      const campaign::Campaign c = campaign::load_campaign(e.file);
      for (auto& n : campaign::check_names(c)) names.push_back(std::move(n));
      for (auto& t : campaign::check_tags(c)) names.push_back(std::move(t));
    }
    std::string what;
    for (const std::string& n : o.checks.only) what += fmt::format(" --only {}{}", n, did_you_mean(n, names));
    for (const std::string& t : o.checks.tags) what += fmt::format(" --tag {}{}", t, did_you_mean(t, names));
    err << fmt::format("hilrig run:{}: no campaign of the suite has such a check\n", what);
    return kBadInput;
  }

  // OUT itself, for the whole suite: locked against a second run, and cleared of the files of
  // a single campaign run there earlier, so none of its results.json or trace sits beside the
  // suite's index as if it were the suite's.
  std::optional<OutputDirectory> out_dir;
  try {
    out_dir.emplace(o.out, OutputDirectory::Holds::Suite);
  } catch (const ForeignOutput& e) {
    err << "hilrig run: " << e.what() << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    return kRigFault;
  }

  std::size_t total_runs = 0;
  for (const auto& p : prepared) total_runs += p->runs.size();
  RunProgress progress(err, progress_mode(o), total_runs, true);
  campaign::StopRequest stop;
  std::optional<StopSignals> signals;
  if (o.handle_signals) signals.emplace(stop);

  // Each campaign writes its own directory and its messages into its own buffers, printed in
  // suite order as soon as every campaign before it is done: the same text for any --jobs.
  const std::size_t n = prepared.size();
  const auto suite_started = wall_start(o.epoch); // a campaign the stop kept from starting dates from here
  std::vector<Ran> ran(n);
  std::vector<std::ostringstream> outs(n);
  std::vector<std::ostringstream> errs(n);
  std::vector<bool> finished(n, false);
  std::size_t printed = 0;
  std::mutex print_mutex;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> junit_held{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      if (stop.requested()) {
        errs[i] << fmt::format("hilrig run: {}: not run (stopped by {})\n", chosen[i].file, stop.reason());
        ran[i].status = kRigFault;
        // Its junit testsuite carries the suite's start and host, as the campaigns that ran.
        ran[i].clock.started_at = iso8601_utc(suite_started);
        ran[i].clock.hostname = host_name();
        ran[i].not_run = fmt::format("not run: the suite was stopped by {}", stop.reason());
      } else {
        ran[i] = execute(o, *prepared[i], o.out / chosen[i].subdir, &stop, progress, outs[i], errs[i],
                         &junit_held);
      }
      const std::lock_guard lock(print_mutex);
      finished[i] = true;
      for (; printed < n && finished[printed]; ++printed) {
        err << errs[printed].str() << std::flush;
        out << outs[printed].str() << std::flush;
      }
    }
  };
  const std::size_t jobs = std::clamp<std::size_t>(o.jobs, 1, n);
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  progress.close();
  signals.reset();

  std::vector<rig::JunitCampaign> junit;
  std::vector<rig::SuiteRow> rows;
  for (std::size_t i = 0; i < n; ++i) {
    status = worst_status(status, ran[i].status);
    rig::SuiteRow row{chosen[i].file, chosen[i].subdir, ran[i].status, ran[i].result, {}};
    if (!ran[i].result)
      row.message = ran[i].not_run.empty() ? "no results: see the command's messages" : ran[i].not_run;
    rows.push_back(std::move(row));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (rows[i].result)
      junit.push_back({&*rows[i].result,
                       chosen[i].file,
                       ran[i].clock,
                       rig::run_log_runs(ran[i].log),
                       ran[i].junit ? &*ran[i].junit : nullptr,
                       {}});
    else // a campaign without results is an error in junit.xml too, not a missing testsuite
      junit.push_back({nullptr,
                       chosen[i].file,
                       ran[i].clock,
                       {},
                       nullptr,
                       ran[i].not_run.empty() ? fmt::format("no results: {} (see the command's messages)",
                                                            rig::exit_words(ran[i].status))
                                              : ran[i].not_run,
                       prepared[i]->c.name});
  }
  const std::string title = "hilrig suite: " + [&] {
    std::string names;
    for (const std::string& f : o.files) names += (names.empty() ? "" : " ") + f;
    return names;
  }();
  try {
    rig::write_file_atomically(o.out / "junit.xml", [&](std::ostream& file) {
      rig::write_junit_suite_xml(title, junit, rig::sink_to(file));
    });
    rig::write_file_atomically(o.out / "report.html", rig::to_suite_index_html(title, rows, status));
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    return kRigFault;
  }
  const rig::SuiteTally tally = rig::tally(rows);
  out << fmt::format("suite: {}; exit {} ({})\n", tally.text(), status, tally.exit_text(status));
  out << fmt::format("report: {}\n", (o.out / "report.html").string());
  return status;
}

} // namespace

std::string interruption_text(const rig::CampaignResult& result, const std::string& out_dir) {
  // The signal stopped a run in the middle, or landed between two runs (the run before it
  // finished whole and the next never started). A run it stopped is in the results (marked
  // interrupted) but is not done: it is not counted among the runs done.
  const bool mid_run = result.last_run_interrupted;
  const std::size_t whole = result.totals.runs - (mid_run && result.totals.runs > 0 ? 1 : 0);
  return fmt::format("hilrig run: interrupted by {}: {} of {} run(s) done, {}; results written to {}",
                     result.interrupted.value_or("a signal"), whole, result.planned_runs,
                     mid_run
                         ? "and the next stopped early with every rig-driven line at its inactive level"
                         : "the signal landed between runs (every run done is whole; none started after it)",
                     out_dir);
}

int worst_status(int a, int b) {
  // Exit statuses rank by how much of the evidence can be trusted: a rig fault (3) means a run
  // did not happen as planned, bad input (2) that nothing ran, a failed check (1) a real verdict.
  return std::max(a, b);
}

int run_campaign(const RunOptions& o, std::ostream& out, std::ostream& err) {
  Prepared p;
  bool selected = true;
  if (const int status = prepare(o, o.file, false, p, selected, err); status != kPassed) return status;
  campaign::StopRequest stop;
  std::optional<StopSignals> signals;
  if (o.handle_signals) signals.emplace(stop);
  RunProgress progress(err, progress_mode(o), p.runs.size(), false);
  const Ran ran = execute(o, p, o.out, o.handle_signals ? &stop : nullptr, progress, out, err);
  progress.close();
  signals.reset(); // the outputs are written: SIGINT/SIGTERM act as usual again
  if (ran.result) out << fmt::format("report: {}\n", (o.out / "report.html").string());
  return ran.status;
}

int run_campaign(const RunOptions& o, std::ostream& err) { return run_campaign(o, err, err); }

int run_campaigns(const RunOptions& o, std::ostream& out, std::ostream& err) {
  if (o.files.size() == 1 && std::filesystem::is_regular_file(o.files.front())) {
    RunOptions one = o;
    one.file = o.files.front();
    return run_campaign(one, out, err);
  }
  return run_suite(o, out, err);
}

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run", "run campaign files (or directories of them: a suite) and write their results");
  cmd->add_option("files", options->files,
                  "campaign files (.toml) and directories (every *.toml under one, sorted); one file: its "
                  "outputs in --out, several: a suite, each campaign in --out/<name>/")
      ->required();
  cmd->add_option("--out", options->out,
                  "directory for results.json, junit.xml, report.html, trace.vcd (a suite: junit.xml, "
                  "report.html and a directory per campaign)")
      ->required()
      ->check(CLI::Validator(
          // An empty path is no directory: bad input, before the campaign is even read.
          [](const std::string& dir) {
            return dir.empty() ? std::string("a directory, not an empty path") : "";
          },
          "DIR"));
  add_seed_option(*cmd, options->seed, "base seed (overrides [campaign] seed)");
  cmd->add_option("--shard", options->shard, "K/N: run only the runs whose index mod N is K (0-based)");
  cmd->add_option("--jobs,-j", options->jobs, "campaigns of a suite run at once (outputs as with 1)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--probe-threads", options->probe_threads,
                  "threads bisecting a debounce check's start phases at once (default: one per core; "
                  "outputs as with 1)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--only", options->checks.only, "run only this check (by name; repeatable)");
  cmd->add_option("--tag", options->checks.tags,
                  "run only the checks with this tag (`tags = [...]`; repeatable)");
  cmd->add_option("--host-link", options->host_link,
                  "how host actions reach the DUT: in-process (default) or modbus-rtu-pty (Modbus RTU on a "
                  "pty pair, served as `hilrig serve` maps the device)")
      ->check(
          CLI::IsMember({std::string(campaign::kInProcessLink), std::string(campaign::kModbusRtuPtyLink)}));
  cmd->add_option(
         "--backend", options->backend,
         "virtual (the in-process bus) or hardware (the rig --rig describes); default: the campaign's "
         "[dut] backend")
      ->check(CLI::IsMember({std::string("virtual"), std::string("hardware")}));
  cmd->add_option("--station", options->station,
                  "the test station's name, written into results.json, junit.xml and report.html")
      ->check(CLI::Validator(
          [](const std::string& v) {
            return campaign::is_label(v) ? std::string() : campaign::label_range();
          },
          "NAME"));
  cmd->add_option("--epoch", options->epoch,
                  "the wall-clock start to write (results.json, junit.xml, can.log's first time), in seconds "
                  "since 1970, instead of now: reproducible outputs (default: SOURCE_DATE_EPOCH when set)")
      ->check(CLI::Validator(
          [](const std::string& v) { return parse_epoch(v) ? std::string() : epoch_range(); }, "SECONDS"));
  cmd->add_option("--rig", options->rig, "the rig config of a hardware run (docs/rig-config.md)");
  cmd->add_flag("--exact-scan", options->exact_scan,
                "virtual DUTs scan every period instead of skipping the scans that change nothing: the "
                "oracle of scan skipping, with byte-identical outputs (docs/virtual-time.md)");
  auto trace = std::make_shared<std::string>(rig::to_string(options->trace));
  cmd->add_option(
         "--trace", *trace,
         "which runs keep trace.vcd / trace-run<i>.vcd and their .gtkw files: all (the first run's and "
         "each run's that did not pass; default), failed (only runs that did not pass: nightly "
         "sweeps), none")
      ->check(CLI::Validator(
          [](const std::string& v) {
            if (rig::trace_policy_named(v)) return std::string();
            return fmt::format("{} is not one of all, failed, none{}", v,
                               did_you_mean(v, rig::trace_policy_names()));
          },
          "all|failed|none"));
  cmd->add_flag(
      "--progress", options->progress_lines,
      "a line per finished run on stderr (outcome, wall time, ETA), also when it is not a terminal");
  cmd->callback([options, trace] {
    keep_freed_heap(); // where it is not glibc's allocator there is nothing to keep
    options->trace = *rig::trace_policy_named(*trace); // checked above
    options->progress = isatty(fileno(stderr)) != 0;
    if (!options->epoch) {
      // The reproducible-builds convention (reproducible-builds.org/specs/source-date-epoch):
      // a malformed value is an error, not ignored.
      if (const char* env = std::getenv("SOURCE_DATE_EPOCH"); env != nullptr) {
        options->epoch = parse_epoch(env);
        if (!options->epoch) {
          std::cerr << "hilrig run: SOURCE_DATE_EPOCH=\"" << env << "\": " << epoch_range() << '\n';
          exit_with(kBadInput);
        }
      }
    }
    const int status = run_campaigns(*options, std::cout, std::cerr);
    if (status != kPassed) exit_with(status);
  });
}

} // namespace hilrig::cli
