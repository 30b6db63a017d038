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
#include "rig/campaign/host_link.hpp"
#include "rig/campaign/run_guards.hpp"
#include "rig/campaign/stop_request.hpp"
#include "rig/checks/brake.hpp"
#include "rig/results/measurement.hpp"
#include "rig/results/motion_record.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

struct RunInputs {
  const Scenario* scenario = nullptr;
  std::string variant;           // the DUT variant for this run
  std::vector<Stimulus> faults;  // signal faults injected on top of the stimuli
  std::optional<Stimulus> probe; // one extra pulse (debounce bisection)
  std::uint64_t seed = 0;
  bool record_motion = true;                  // follow every count change (brake checks need it)
  const HostLinkFactory* host_link = nullptr; // how host actions reach the DUT (null: in process)
  const StopRequest* stop = nullptr;          // when requested, the run stops at its next event
  RunGuards guards{};                         // a stalled or flooding run stops with a rig fault
  bool exact_scan = false;                    // the DUT scans every period (the skipping's oracle)
};

struct VirtualRun {
  std::shared_ptr<TraceRecorder> trace;
  signals::MotionProfile profile; // counts
  // The count changes as checks::append_motion keeps them (what the brake check reads: the
  // start, the last change and the end), so it does not grow with the run.
  std::vector<checks::PositionSample> motion;
  std::vector<rig::MotionEvent> motion_events; // a plant's inputs as they changed, its standstills
  // A plant's run: the encoder count's changes as played (motion is then the plant's own
  // samples). Empty otherwise: motion is the count changes.
  std::vector<checks::PositionSample> counts;
  std::vector<rig::Observation> observations; // host reads
  std::vector<rig::Measurement> handshakes;   // host writes: time to Acknowledge
  std::vector<rig::Measurement> rig_timing;   // hardware runs: the rig's own timing (wake-ups, edges)
  std::string rig_fault;                      // hardware runs: why the run stopped early ("" when it did not)
  // Virtual time: the board saw exactly the profile's edges, so its standstill is known
  // exactly. A hardware run sets it false: the edges went out with the RT loop's jitter and
  // only the count changes are evidence.
  bool exact_motion = true;
  // The run stopped early (a stop request, or a host-link or model failure in the middle):
  // what was captured up to then is kept, every rig-driven line was driven to its inactive
  // level at that time, and rig_fault says why. interrupted: it was a stop request.
  bool interrupted = false;
};

// Throws RigFault when the scenario cannot be simulated.
[[nodiscard]] VirtualRun run_virtual(const RunInputs& inputs);

} // namespace hilrig::campaign
