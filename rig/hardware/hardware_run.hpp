#pragma once
// One run of a scenario on the rig. The output edges are precomputed (edge_schedule.hpp)
// and played by the RT loop (rig/rt) on its own SCHED_FIFO thread, which also drains the
// captured input edges with their kernel timestamps; the resolver's CAN angle stream plays on
// its own real-time thread (resolver_stream.hpp); the host actions run on an ordinary thread
// at their scheduled times; this thread moves samples and sent frames out of the rings. Everything captured
// goes into a TraceRecorder, so the same checks judge it as a virtual run. Times are CLOCK_MONOTONIC from the
// run's start.
//
// A rig fault (an output edge later than rt.edge_tolerance, CAN bus-off or the interface
// going down, CAN frames lost to an overrun, a lost host link, lost samples) stops the run; what was captured
// is kept and the fault is in VirtualRun::rig_fault.

#include "core/time.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/hardware/drive_plan.hpp"
#include "rig/hardware/rig_config.hpp"
#include "rig/hardware/rig_ports.hpp"

namespace hilrig::hardware {

struct HardwareRunOptions {
  RtConfig rt;
  bool realtime = true;   // make the loop's and the stream's threads real-time (SCHED_FIFO, pinned, locked)
  Nanos lead{50'000'000}; // from setting up to the run's start
  Nanos poll_period{500'000};       // longest the loop sleeps without draining inputs
  Nanos resolver_period{1'000'000}; // one resolver angle frame every period
};

[[nodiscard]] campaign::VirtualRun run_hardware(const campaign::RunInputs& in, const DrivePlan& plan,
                                                RigPorts& ports, const HardwareRunOptions& options);

} // namespace hilrig::hardware
