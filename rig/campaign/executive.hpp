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

class Executive {
public:
  explicit Executive(const Campaign& campaign) : campaign_(campaign) {}

  // Runs one run. A rig fault inside the run is reported in result.error, not thrown.
  [[nodiscard]] RunOutput run(const RunSpec& run) const;

  // Runs the given runs (e.g. one shard) in order into a finalized CampaignResult.
  // progress(i, n, run) is called before each run.
  using Progress = std::function<void(std::size_t done, std::size_t total, const RunSpec& run)>;
  using TraceSink = std::function<void(const RunSpec& run, const RunOutput& out)>;
  [[nodiscard]] rig::CampaignResult run_all(const std::vector<RunSpec>& runs, std::uint64_t seed,
                                            rig::Shard shard, const Progress& progress = {},
                                            const TraceSink& sink = {}) const;

private:
  const Campaign& campaign_;
};

} // namespace hilrig::campaign
