#pragma once
// The executive: runs a campaign's runs in virtual time. Each run builds a Scheduler, a
// TraceRecorder and a VirtualBus, attaches the DUT adapter by the wiring, schedules the
// encoder edges solved from the motion, the discrete stimuli, signal faults and host
// actions, runs to the end time, then hands the trace and the check parameters to the
// checks (rig/checks/registry.hpp). Same campaign + seed -> identical results.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/trace.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/campaign/host_link.hpp"
#include "rig/campaign/stop_request.hpp"
#include "rig/checks/check_params.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::campaign {

// Something the rig itself could not do (no backend, a model that threw): exit status 3.
class RigFault : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct RunOutput {
  rig::RunResult result;
  std::shared_ptr<TraceRecorder> trace; // the run's full trace (VCD, candump)
};

struct RunInputs;
struct VirtualRun;
// Carries out one run and returns what it captured: run_virtual by default; the hardware
// backend (rig/hardware) plays the same inputs on a real rig.
using RunBackend = std::function<VirtualRun(const RunInputs&)>;

class Executive {
public:
  explicit Executive(const Campaign& campaign, RunBackend backend = {});

  // How host actions reach the DUT (rig/campaign/host_link.hpp); empty: in process.
  void use_host_link(HostLinkFactory link) { host_link_ = std::move(link); }
  // Once `stop` is requested, the current run stops at its next event (every rig-driven line
  // driven inactive, the run marked interrupted) and no further run starts. Outlives run_all.
  void stop_on(const StopRequest* stop) { stop_ = stop; }
  // Every virtual DUT scans every period instead of skipping the scans that change nothing
  // (docs/virtual-time.md): the oracle the skipping is compared against, byte for byte.
  void scan_every_period(bool on) { exact_scan_ = on; }
  // A debounce check's start phases are bisected on up to `threads` threads (virtual runs are
  // independent); the results are the same for any count. 1 (the default): in turn.
  void probe_threads(std::size_t threads) { probe_threads_ = threads; }

  // Runs one run. A rig fault inside the run is reported in result.error, not thrown.
  [[nodiscard]] RunOutput run(const RunSpec& run) const;

  // Runs the given runs (e.g. one shard) in order into a finalized CampaignResult.
  // progress(i, n, run) is called before each run.
  using Progress = std::function<void(std::size_t done, std::size_t total, const RunSpec& run)>;
  // sink(run, out) after each run: returns the trace file it wrote for the run (relative to
  // the results), "" when it kept none; the run's result records it. A sink that throws gives
  // that run a rig error (its checks kept) and the campaign goes on.
  using TraceSink = std::function<std::string(const RunSpec& run, const RunOutput& out)>;
  // record(run) after each run: when given, each finished run is handed to it and not kept,
  // so the returned result holds no runs (the caller folds them, e.g. from a rig::RunLog) and
  // memory does not grow with the run count. Without it, the runs are in the returned result.
  using Recorder = std::function<void(const rig::RunResult& run)>;
  [[nodiscard]] rig::CampaignResult run_all(const std::vector<RunSpec>& runs, std::uint64_t seed,
                                            rig::Shard shard, const Progress& progress = {},
                                            const TraceSink& sink = {}, const Recorder& record = {}) const;
  // The campaign's facts for these runs, before any has run (the run log's header).
  [[nodiscard]] rig::CampaignResult planned(const std::vector<RunSpec>& runs, std::uint64_t seed,
                                            rig::Shard shard) const;

private:
  // A debounce check's bisections, one per start phase, in the order of its probe_starts.
  [[nodiscard]] std::vector<checks::PhaseBisection> bisect_phases(const RunInputs& in, const CheckSpec& c,
                                                                  const checks::DebounceParams& d) const;

  const Campaign& campaign_;
  RunBackend backend_;
  HostLinkFactory host_link_;
  const StopRequest* stop_ = nullptr;
  bool exact_scan_ = false;
  std::size_t probe_threads_ = 1;
};

} // namespace hilrig::campaign
