#pragma once
// The run's motion as the results keep it (rig::MotionRecord): the trajectory the encoder
// played, sampled evenly and at its knots (every segment start, when there are few), plus
// the instants of the events, so the report plots speed and position from the results.

#include <vector>

#include "rig/results/motion_record.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

// Segments beyond which the knots are not kept (a plant's every integration step is one).
inline constexpr std::size_t kMotionKnotsKept = 400;
// Points of an evenly sampled trajectory.
inline constexpr std::size_t kMotionSamples = 500;

// The profile over [its start, end] with `events` (in time order) and a point at each.
[[nodiscard]] rig::MotionRecord record_motion(const signals::MotionProfile& profile, Nanos end,
                                              std::vector<rig::MotionEvent> events);

} // namespace hilrig::campaign
