#pragma once
// When a motion profile comes to rest for good: what a brake stop time is measured to when
// the rig knows the trajectory (virtual time), instead of guessing it from count changes.

#include <optional>

#include "core/time.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::signals {

// The first instant at or after `from` from which the profile never moves again: the end
// of its last moving segment (velocity or acceleration not zero), or `from` when nothing
// moves after it. nullopt when the profile ends in an open-ended moving segment.
[[nodiscard]] std::optional<Nanos> standstill_after(const MotionProfile& profile, Nanos from);

} // namespace hilrig::signals
