#include "rig/cli/run_command.hpp"

#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "core/trace.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/modbus_host_link.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/output_dir.hpp"
#include "rig/cli/serve_devices.hpp"
#include "rig/cli/stop_signals.hpp"
#include "rig/hardware/hardware_backend.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::cli {

namespace {

constexpr std::size_t kMaxFailureTraces = 20;

// Written to a temporary file and renamed, so a crash leaves a whole VCD or none (and a full
// disk no *.tmp).
void write_trace_files(const std::filesystem::path& dir, const std::string& stem,
                       const TraceRecorder& trace) {
  std::ostringstream vcd;
  write_vcd(trace, vcd);
  rig::write_file_atomically(dir / (stem + ".vcd"), vcd.str());
}

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
  if (o.rig.empty()) {
    if (o.backend == "hardware") {
      err << "hilrig run: --backend hardware needs --rig RIG.toml (docs/rig-config.md)\n";
      return kBadInput;
    }
    err << fmt::format("hilrig run: rig fault: [dut] backend \"{}\" runs on a rig: give --rig RIG.toml\n",
                       asked);
    return kRigFault;
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

std::string interruption_text(const rig::CampaignResult& result, const std::string& out_dir) {
  // The signal stopped a run in the middle, or landed between two runs (the run before it
  // finished whole and the next never started).
  const bool mid_run = !result.runs.empty() && result.runs.back().interrupted;
  return fmt::format("hilrig run: interrupted by {}: {} of {} run(s) done, {}; results written to {}",
                     result.interrupted.value_or("a signal"), result.runs.size(), result.planned_runs,
                     mid_run
                         ? "the last stopped early with every rig-driven line at its inactive level"
                         : "the signal landed between runs (every run done is whole; none started after it)",
                     out_dir);
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
  const std::optional<campaign::HostLinkFactory> link = host_link_for(o, c, err);
  if (!link) return kBadInput;
  std::optional<hardware::RigConfig> rig;
  if (const int status = choose_backend(o, c, rig, err); status != kPassed) return status;

  std::optional<OutputDirectory> out_dir;
  try {
    out_dir.emplace(o.out);
  } catch (const ForeignOutput& e) {
    err << "hilrig run: " << e.what() << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    err << "hilrig run: rig fault: " << e.what() << '\n';
    return kRigFault;
  }
  try {
    campaign::Executive exec(c, rig ? hardware::hardware_backend(*rig, c.file, o.rig_ports)
                                    : campaign::RunBackend{});
    exec.use_host_link(*link);
    campaign::StopRequest stop;
    std::optional<StopSignals> signals;
    if (o.handle_signals) {
      signals.emplace(stop);
      exec.stop_on(&stop);
    }
    bool can_used = false;
    std::size_t failure_traces = 0;
    std::ofstream can_log;
    const auto progress = [&](std::size_t done, std::size_t total, const campaign::RunSpec& run) {
      if (o.progress)
        err << fmt::format("\r[{}/{}] run {} {}\x1b[K", done + 1, total, run.index, run.label) << std::flush;
      else if (o.progress_lines)
        err << fmt::format("[{}/{}] run {} {}\n", done + 1, total, run.index, run.label) << std::flush;
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
        can_log.flush();
        if (!can_log) throw campaign::RigFault(fmt::format("cannot write {}", (o.out / "can.log").string()));
      }
    };
    const rig::Shard part{static_cast<std::uint32_t>(shard->first),
                          static_cast<std::uint32_t>(shard->second)};
    // Each run is appended to the run log as it finishes (and not kept), so a campaign costs the
    // same per run however long it is, and a crash or SIGKILL leaves every finished run; the
    // log is folded into results.json below.
    rig::RunLog log(o.out / rig::kRunLogName, exec.planned(runs, seed, part));
    const rig::CampaignResult done =
        exec.run_all(runs, seed, part, progress, sink, [&](const rig::RunResult& run) { log.append(run); });
    rig::CampaignResult result = rig::read_run_log(log.path());
    result.interrupted = done.interrupted;
    rig::finalize(result);
    if (o.progress) err << '\n';
    rig::write_results_file(o.out / "results.json", result);
    rig::write_file_atomically(o.out / "junit.xml", rig::to_junit_xml(result));
    rig::write_file_atomically(o.out / "report.html", rig::to_report_html(result));

    signals.reset(); // the outputs are written: SIGINT/SIGTERM act as usual again
    const auto& t = result.totals;
    err << fmt::format("{}: {} run(s), {} passed, {} failed, {} errored; faults caught {}/{}; verdict {}\n",
                       c.name, t.runs, t.runs_passed, t.runs_failed, t.runs_errored, t.faults_caught,
                       t.faults, rig::to_string(result.verdict));
    for (const auto& run : result.runs)
      if (!run.error.empty())
        err << fmt::format("run {} ({}): rig fault: {}\n", run.index, run.name, run.error);
    if (result.interrupted) {
      err << interruption_text(result, o.out.string()) << '\n';
      return kRigFault;
    }
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
  cmd->add_option("--seed", options->seed, "base seed (overrides [campaign] seed; 0 or more)")
      ->check(CLI::Validator(
          [](const std::string& v) {
            return v.starts_with("-") ? std::string("a seed is 0 or more (an unsigned 64-bit integer)") : "";
          },
          "SEED>=0"));
  cmd->add_option("--shard", options->shard, "K/N: run only the runs whose index mod N is K (0-based)");
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
  cmd->add_option("--rig", options->rig, "the rig config of a hardware run (docs/rig-config.md)");
  cmd->add_flag("--progress", options->progress_lines,
                "a progress line per run on stderr, also when it is not a terminal");
  cmd->callback([options] {
    options->progress = isatty(fileno(stderr)) != 0;
    const int status = run_campaign(*options, std::cerr);
    if (status != kPassed) exit_with(status);
  });
}

} // namespace hilrig::cli
