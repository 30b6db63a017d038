#include "signals/standstill.hpp"

#include <algorithm>

namespace hilrig::signals {

std::optional<Nanos> standstill_after(const MotionProfile& profile, Nanos from) {
  const auto& segments = profile.segments();
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
    if (it->velocity == 0.0 && it->acceleration == 0.0) continue;
    if (it->duration == Nanos::max()) return std::nullopt;
    return std::max(it->end(), from);
  }
  return from;
}

} // namespace hilrig::signals
