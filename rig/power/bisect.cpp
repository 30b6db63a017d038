#include "rig/power/bisect.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace hilrig::power {

BisectResult bisect_threshold(const BisectSpec& spec, const std::function<Probe(double)>& probe) {
  BisectResult r;
  const auto ask = [&](double deviation) {
    ++r.probes;
    return probe(deviation);
  };
  const auto stopped = [&](Probe p, double deviation) {
    if (p == Probe::Error)
      r.reason = fmt::format("the check could not be judged at deviation {:g}", deviation);
    return p == Probe::Error;
  };
  const Probe nominal = ask(0.0);
  if (stopped(nominal, 0.0)) return r;
  if (nominal == Probe::Fail) {
    r.reason = "fails at the nominal value";
    return r;
  }
  // Bracket: double the step until the check fails or the knob's range is used up.
  double lo = 0.0;
  double hi = std::min(spec.first_step, spec.max_deviation);
  for (;;) {
    if (r.probes >= spec.max_probes) {
      r.reason = fmt::format("no failure within {} probes (passes at deviation {:g})", spec.max_probes, lo);
      r.last_pass = lo;
      return r;
    }
    const Probe p = ask(hi);
    if (stopped(p, hi)) return r;
    if (p == Probe::Fail) break;
    lo = hi;
    if (hi >= spec.max_deviation) {
      r.last_pass = lo;
      r.reason = fmt::format("never fails within the knob's range (passes at deviation {:g})", lo);
      return r;
    }
    hi = std::min(hi * 2.0, spec.max_deviation);
  }
  // Narrow [lo passes, hi fails] to the resolution.
  while (hi - lo > spec.resolution && r.probes < spec.max_probes) {
    double mid = lo + (hi - lo) / 2.0;
    if (spec.integer) mid = std::max(lo + 1.0, static_cast<double>(static_cast<long long>(mid)));
    const Probe p = ask(mid);
    if (stopped(p, mid)) return r;
    (p == Probe::Fail ? hi : lo) = mid;
  }
  r.threshold = hi;
  r.last_pass = lo;
  return r;
}

} // namespace hilrig::power
