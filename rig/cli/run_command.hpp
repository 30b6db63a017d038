#pragma once
// `hilrig run FILE.toml --out DIR [--seed S] [--shard K/N]`: runs a campaign (in virtual
// time by default) and writes DIR/results.json, junit.xml, report.html, trace.vcd (the
// shard's first run; also trace-run<i>.vcd for up to 20 runs that did not pass) and
// can.log when CAN was used. Exit: 0 all passed, 1 a check failed, 2 bad input, 3 a rig fault
// (also a run stopped by SIGINT/SIGTERM: what ran is written, the stopped run marked interrupted).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "rig/campaign/host_link.hpp"
#include "rig/hardware/rig_ports.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::cli {

void add_run_command(CLI::App& app);

struct RunOptions {
  std::string file;
  std::filesystem::path out;
  std::optional<std::uint64_t> seed; // overrides [campaign] seed
  std::string shard = "0/1";         // K/N, K in 0..N-1: runs whose index mod N is K
  bool progress = false;             // a progress line on err (a terminal: rewritten in place)
  bool progress_lines = false;       // --progress: one line per run, also when err is not a terminal
  std::string host_link{campaign::kInProcessLink}; // --host-link: in-process or modbus-rtu-pty
  campaign::HostLinkFactory host_link_factory;     // set by a caller: the link to use instead
  bool handle_signals = true; // SIGINT/SIGTERM stop the run, outputs inactive, results written, exit 3
  // --backend: "virtual" or "hardware"; "" follows the campaign's [dut] backend (or --rig).
  std::string backend;
  std::string rig;                     // --rig: the rig config (docs/rig-config.md) of a hardware run
  hardware::RigPortsFactory rig_ports; // set by a caller: the rig's ports instead of its drivers
};

// Does the whole command and returns its exit status; messages go to err.
[[nodiscard]] int run_campaign(const RunOptions& options, std::ostream& err);

// What `hilrig run` says of a campaign a signal stopped: how many runs are done, and whether
// the last was stopped early or the signal landed between runs.
[[nodiscard]] std::string interruption_text(const rig::CampaignResult& result, const std::string& out_dir);

// "K/N" -> (K, N); nullopt unless 0 <= K < N.
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> parse_shard(const std::string& text);

} // namespace hilrig::cli
