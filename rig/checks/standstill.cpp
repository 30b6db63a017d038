#include "rig/checks/standstill.hpp"

namespace hilrig::checks {

std::optional<Standstill> exact_standstill(std::optional<Nanos> at, Nanos trace_end) {
  if (!at || *at > trace_end) return std::nullopt;
  return Standstill{*at, *at};
}

std::optional<Standstill> standstill_interval(std::span<const PositionSample> motion, Nanos from,
                                              Nanos trace_end) {
  const auto last = standstill_after(motion, from, trace_end);
  if (!last) return std::nullopt;
  // The change before the last one bounds the final speed: one count in (last - before).
  Nanos before = *last;
  for (std::size_t i = 1; i < motion.size(); ++i)
    if (motion[i].time == *last && motion[i].position != motion[i - 1].position) before = motion[i - 1].time;
  const Nanos latest = *last + (*last - before);
  const Nanos end = motion.empty() ? trace_end : std::max(motion.back().time, trace_end);
  if (latest > end) return std::nullopt;
  return Standstill{*last, latest};
}

} // namespace hilrig::checks
