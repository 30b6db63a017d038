#include "rig/checks/debounce.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace hilrig::checks {

Bisection bisect_boundary(const PulseProbe& accepted, Nanos narrow, Nanos wide, Nanos resolution) {
  if (narrow >= wide) throw std::invalid_argument("bisect_boundary: narrow must be below wide");
  if (resolution <= Nanos{0}) throw std::invalid_argument("bisect_boundary: resolution must be positive");
  Bisection b;
  const auto probe = [&](Nanos w) {
    const bool ok = accepted(w);
    b.probes.push_back({w, ok});
    return ok;
  };
  const bool narrow_ok = probe(narrow);
  const bool wide_ok = probe(wide);
  b.rejected = narrow;
  b.accepted = wide;
  b.bracketed = !narrow_ok && wide_ok;
  if (!b.bracketed) return b;
  while (b.accepted - b.rejected > resolution) {
    const Nanos mid = b.rejected + (b.accepted - b.rejected) / 2;
    if (probe(mid)) {
      b.accepted = mid;
    } else {
      b.rejected = mid;
    }
  }
  return b;
}

CheckResult check_debounce(const Bisection& bisection, const DebounceSpec& spec) {
  CheckResult r;
  r.kind = "debounce";
  for (const auto& p : bisection.probes) r.probes.push_back(rig::Probe{p.width, p.accepted});
  const Nanos lo = spec.filter - spec.tolerance;
  const Nanos hi = spec.filter + spec.tolerance;
  if (!bisection.bracketed) {
    r.measurements.push_back(failure(
        spec.name + ".boundary",
        fmt::format("boundary not bracketed: narrowest probe {} us {}, widest {} us {}",
                    to_us(bisection.rejected),
                    bisection.probes.empty() || !bisection.probes[0].accepted ? "rejected" : "accepted",
                    to_us(bisection.accepted),
                    bisection.probes.size() < 2 || bisection.probes[1].accepted ? "accepted" : "rejected")));
  } else {
    r.measurements.push_back(
        measure_time(spec.name + ".boundary", bisection.accepted, TimeUnit::Us, lo, hi,
                     fmt::format("pulses of {} us rejected, {} us accepted; filter {} us ± {} us",
                                 to_us(bisection.rejected), to_us(bisection.accepted), to_us(spec.filter),
                                 to_us(spec.tolerance))));
    r.measurements.push_back(measure_time(spec.name + ".resolution", bisection.accepted - bisection.rejected,
                                          TimeUnit::Us, std::nullopt, std::nullopt,
                                          "width of the final bracket"));
  }
  std::size_t misjudged = 0;
  std::string first = "every probe judged as the filter says";
  for (const auto& p : bisection.probes) {
    const bool wrong = (p.accepted && p.width < lo) || (!p.accepted && p.width > hi);
    if (wrong && misjudged++ == 0) {
      first = fmt::format("a {} us pulse was {}", to_us(p.width), p.accepted ? "accepted" : "rejected");
    }
  }
  r.measurements.push_back(
      measure(spec.name + ".misjudged", static_cast<double>(misjudged), "", std::nullopt, 0.0, first));
  return r;
}

} // namespace hilrig::checks
