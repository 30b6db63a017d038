#pragma once
// The campaign's motion, built into a MotionProfile in encoder counts (X4: four counts
// per encoder line), with the instants a press stroke applies its brake.

#include <string>
#include <vector>

#include "rig/campaign/campaign.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

struct BrakeApplied {
  Nanos at;
  std::string line; // rig line to drive high, "" when none
};

struct BuiltMotion {
  signals::MotionProfile profile; // counts, counts/s
  std::vector<BrakeApplied> brakes;
};

// Throws CampaignError (at the move) when a move cannot follow the one before it, e.g. a
// dwell or a trapezoid while the shaft still turns.
[[nodiscard]] BuiltMotion build_motion(const std::string& file, const MotionSpec& motion,
                                       const EncoderSpec& encoder);

} // namespace hilrig::campaign
