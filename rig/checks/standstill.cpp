#include "rig/checks/standstill.hpp"

#include <cmath>

namespace hilrig::checks {

std::optional<Nanos> stop_count_standstill(const std::function<double(Nanos)>& position,
                                           const StopCountRule& rule, Nanos from, Nanos until) {
  const auto still = [&](Nanos t) {
    return std::abs(std::floor(position(t)) - std::floor(position(t - rule.window))) < rule.counts;
  };
  if (until < from) return std::nullopt;
  if (still(from)) return from - rule.window;
  constexpr Nanos kStep{10'000};
  for (Nanos lo = from; lo < until;) {
    Nanos hi = std::min(lo + kStep, until);
    if (still(hi)) {
      while (hi - lo > Nanos{1}) { // lo moving, hi still: the first still instant, to 1 ns
        const Nanos mid = lo + (hi - lo) / 2;
        (still(mid) ? hi : lo) = mid;
      }
      return hi - rule.window;
    }
    lo = hi;
  }
  return std::nullopt;
}

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
