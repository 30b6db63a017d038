#include "rig/rt/wakeup_trace.hpp"

#include <algorithm>
#include <cmath>

#include "rig/rt/rt_loop.hpp"

namespace hilrig::rig {

WakeupTrace::WakeupTrace(std::size_t capacity) : stamps_(capacity) {
  // value-initialised: every page is written now, not on the loop's first store into it
}

Spread spread_of(std::vector<Nanos> samples) {
  Spread s;
  if (samples.empty()) return s;
  std::sort(samples.begin(), samples.end());
  const auto rank = [&](double q) {
    const auto r = static_cast<std::size_t>(std::ceil(q * static_cast<double>(samples.size())));
    return samples[std::max<std::size_t>(r, 1) - 1];
  };
  s.p50 = rank(0.50);
  s.p99 = rank(0.99);
  s.max = samples.back();
  return s;
}

WakeupBreakdown summarize(std::span<const WakeupStamps> stamps) {
  WakeupBreakdown b;
  b.wakeups = stamps.size();
  std::vector<Nanos> latency, work, ahead;
  latency.reserve(stamps.size());
  work.reserve(stamps.size());
  ahead.reserve(stamps.size());
  for (const WakeupStamps& s : stamps) {
    latency.push_back(s.woke - s.due);
    work.push_back(s.done - s.woke);
    ahead.push_back(s.due - s.asleep);
  }
  b.latency = spread_of(std::move(latency));
  b.work = spread_of(std::move(work));
  b.ahead = spread_of(std::move(ahead));
  return b;
}

Spread clock_read_cost(std::size_t pairs) {
  std::vector<Nanos> cost;
  cost.reserve(pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    const Nanos a = monotonic_now();
    const Nanos b = monotonic_now();
    cost.push_back(b - a);
  }
  return spread_of(std::move(cost));
}

} // namespace hilrig::rig
