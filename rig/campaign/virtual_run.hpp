#pragma once
// One simulation of a scenario in virtual time: the DUT on the virtual bus, driven by the
// encoder, stimuli, signal faults and host actions, to the scenario's end. Internal to
// the executive; the checks are judged afterwards from what this returns.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/trace.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/checks/brake.hpp"
#include "rig/results/measurement.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

struct RunInputs {
  const Scenario* scenario = nullptr;
  std::string variant;           // the DUT variant for this run
  std::vector<Stimulus> faults;  // signal faults injected on top of the stimuli
  std::optional<Stimulus> probe; // one extra pulse (debounce bisection)
  std::uint64_t seed = 0;
  bool record_motion = true; // keep every count change (brake checks need it; it is large)
};

struct VirtualRun {
  std::shared_ptr<TraceRecorder> trace;
  signals::MotionProfile profile;             // counts
  std::vector<checks::PositionSample> motion; // every count change (and the start and end)
  std::vector<rig::Observation> observations; // host reads
  std::vector<rig::Measurement> handshakes;   // host writes: time to Acknowledge
};

// Throws RigFault when the scenario cannot be simulated.
[[nodiscard]] VirtualRun run_virtual(const RunInputs& inputs);

} // namespace hilrig::campaign
