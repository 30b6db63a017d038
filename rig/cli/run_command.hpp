#pragma once
// `hilrig run FILE.toml --out DIR [--seed S] [--shard K/N]`: runs a campaign (in virtual
// time by default) and writes DIR/results.json, junit.xml, report.html, trace.vcd (the
// shard's first run; also trace-run<i>.vcd for up to 20 runs that did not pass; --trace failed
// keeps only the latter, --trace none neither) and can.log when CAN was used. Exit: 0 all passed, 1 a check
// failed, 2 bad input, 3 a rig fault (also a run stopped by SIGINT/SIGTERM: what ran is written, the stopped
// run marked interrupted).
//
// `hilrig run A.toml B.toml DIR ... --out OUT [--jobs N]`: a suite (a directory stands for
// every *.toml under it, sorted): each campaign's outputs in OUT/<its name>/, one junit.xml
// with a testsuite per campaign and an index report.html linking each campaign's report in
// OUT; exit status the worst of the campaigns' (3 > 2 > 1 > 0). Every campaign is read and
// checked before the first one runs. --jobs N runs N campaigns at once; their outputs are the
// same as with --jobs 1 (but for junit.xml's wall-clock attributes).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "rig/cli/cli_fwd.hpp"

#include "rig/campaign/check_selection.hpp"
#include "rig/campaign/host_link.hpp"
#include "rig/campaign/stop_request.hpp"
#include "rig/hardware/rig_ports.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::cli {

void add_run_command(CLI::App& app);

struct RunOptions {
  std::string file;               // one campaign (run_campaign)
  std::vector<std::string> files; // campaign files and directories (run_campaigns)
  std::filesystem::path out;
  std::optional<std::uint64_t> seed; // overrides [campaign] seed
  std::string shard = "0/1";         // K/N, K in 0..N-1: runs whose index mod N is K
  std::size_t jobs = 1;              // campaigns of a suite run at once
  std::size_t probe_threads = 0;     // a debounce check's phases bisected at once (0: one per core)
  campaign::CheckSelection checks;   // --only NAME, --tag T: a subset of the checks
  bool progress = false;             // a progress line on err (a terminal: rewritten in place)
  bool progress_lines = false;       // --progress: one line per run, also when err is not a terminal
  std::string host_link{campaign::kInProcessLink}; // --host-link: in-process or modbus-rtu-pty
  campaign::HostLinkFactory host_link_factory;     // set by a caller: the link to use instead
  bool exact_scan = false;    // --exact-scan: DUTs scan every period (the oracle of scan skipping)
  bool handle_signals = true; // SIGINT/SIGTERM stop the run, outputs inactive, results written, exit 3
  // --backend: "virtual" or "hardware"; "" follows the campaign's [dut] backend (or --rig).
  std::string backend;
  // --epoch or SOURCE_DATE_EPOCH: the wall-clock start written (results.json's started_at,
  // junit.xml's timestamp, can.log's epoch), seconds since 1970, instead of now: reproducible
  // outputs. Empty: now.
  std::optional<std::int64_t> epoch;
  rig::TracePolicy trace = rig::TracePolicy::All; // --trace: which runs keep their trace files
  std::string station;                 // --station: the test station's name, carried by the outputs ("" none)
  std::string rig;                     // --rig: the rig config (docs/rig-config.md) of a hardware run
  hardware::RigPortsFactory rig_ports; // set by a caller: the rig's ports instead of its drivers
};

// One campaign (options.file) into options.out. Returns the exit status; the summary line
// and the report's path go to out, everything else (errors, progress) to err.
[[nodiscard]] int run_campaign(const RunOptions& options, std::ostream& out, std::ostream& err);
// The same, with the summary on err as well (callers that read one stream).
[[nodiscard]] int run_campaign(const RunOptions& options, std::ostream& err);

// The command: options.files as one campaign (a single file: its outputs in options.out, as
// run_campaign) or as a suite (anything else). Returns the exit status.
[[nodiscard]] int run_campaigns(const RunOptions& options, std::ostream& out, std::ostream& err);

// What `hilrig run` says of a campaign a signal stopped: how many runs are done, and whether
// the last was stopped early or the signal landed between runs.
[[nodiscard]] std::string interruption_text(const rig::CampaignResult& result, const std::string& out_dir);

// The worst of two exit statuses: 3 (rig fault) > 2 (bad input) > 1 (a check failed) > 0.
[[nodiscard]] int worst_status(int a, int b);

// "K/N" -> (K, N); nullopt unless 0 <= K < N.
[[nodiscard]] std::optional<std::pair<std::size_t, std::size_t>> parse_shard(const std::string& text);

} // namespace hilrig::cli
