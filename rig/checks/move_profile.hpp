#pragma once
// The step rate a programmed move is expected to follow, worked out from the SMD23E manual's
// profile rules (seeds/003 L919-L928, docs/spec/smd23e.md §3.2), not taken from the model
// (models/smd23e/kinematics.hpp): the check must not trust the board it judges. At its start
// the rate jumps from 0 to the Starting Speed, rises at the Acceleration to the Programmed
// Speed, cruises there and falls at the Deceleration to the Starting Speed exactly at the
// target, where the motor stops: a trapezoid. A move too short to reach the Programmed Speed
// accelerates only as far as still lets it decelerate to the Starting Speed at the target: a
// triangle. Linear ramps only (Acceleration Jerk 0, L891): the manual does not define the
// S-curves of the other values well enough to draw (L901, L908).

#include <vector>

#include "core/time.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::checks {

struct MoveProfile {
  Nanos start{0};            // when the move was commanded
  double starting_speed = 0; // v_s, steps/s (the configuration's, L863)
  double speed = 0;          // v_p, steps/s, >= v_s (L2494)
  double accel = 0;          // a, steps/s² (programmed in steps/ms/s: x 1000, L848-L851)
  double decel = 0;          // d, steps/s²
  double steps = 0;          // N > 0: the move's length
};

// The profile's knots, joined by straight lines: (start, v_s), (end of the ramp up, peak),
// (start of the ramp down, peak) when it cruises, (start + T, v_s). Times to the ns.
[[nodiscard]] std::vector<rig::RatePoint> expected_step_rate(const MoveProfile& p);

} // namespace hilrig::checks
