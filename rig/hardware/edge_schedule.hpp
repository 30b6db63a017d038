#pragma once
// The RT loop's output schedule, precomputed before the run: the rig's drive (encoder
// edges solved from the motion, stimuli, signal faults, brake) played in virtual time by
// the same code the virtual run uses, each level change recorded instead of driven.

#include <cstdint>
#include <vector>

#include "core/rt_ports.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/checks/brake.hpp"
#include "rig/hardware/drive_plan.hpp"

namespace hilrig::hardware {

struct EdgeSchedule {
  std::vector<ScheduledEdge> edges; // time order; line = index into DrivePlan::outputs
  campaign::BuiltMotion motion;
  std::vector<checks::PositionSample> positions; // as checks::append_motion keeps them, to the end
};

// in: the run's scenario, faults, probe and whether to record the motion.
// Throws campaign::RigFault for a stimulus on a line the plan does not drive.
[[nodiscard]] EdgeSchedule build_schedule(const campaign::RunInputs& in, const DrivePlan& plan);

} // namespace hilrig::hardware
