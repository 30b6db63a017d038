#include "rig/checks/debounce.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

namespace hilrig::checks {

Bisection bisect_boundary(const PulseProbe& accepted, Nanos narrow, Nanos wide, Nanos resolution,
                          std::span<const Nanos> first) {
  if (narrow >= wide) throw std::invalid_argument("bisect_boundary: narrow must be below wide");
  if (resolution <= Nanos{0}) throw std::invalid_argument("bisect_boundary: resolution must be positive");
  Bisection b;
  std::optional<Nanos> rejected; // the widest rejected so far
  std::optional<Nanos> taken;    // the narrowest accepted so far
  const auto probe = [&](Nanos w) {
    const bool ok = accepted(w);
    b.probes.push_back({w, ok});
    if (ok && (!taken || w < *taken)) taken = w;
    if (!ok && (!rejected || w > *rejected)) rejected = w;
  };
  for (const Nanos w : first) probe(w);
  const bool bracket_below = !rejected;
  const bool bracket_above = !taken;
  if (bracket_below) probe(narrow);
  if (bracket_above) probe(wide);
  b.rejected = rejected.value_or(narrow);
  b.accepted = taken.value_or(wide);
  // A board that rejected a pulse wider than one it accepted has no single boundary.
  b.bracketed = rejected && taken && *rejected < *taken;
  if (!b.bracketed) return b;
  while (b.accepted - b.rejected > resolution) {
    const Nanos mid = b.rejected + (b.accepted - b.rejected) / 2;
    probe(mid);
    b.rejected = *rejected;
    b.accepted = *taken;
    if (b.rejected >= b.accepted) { // not monotonic in the width after all
      b.bracketed = false;
      return b;
    }
  }
  return b;
}

namespace {

std::string ms(Nanos t) { return fmt::format("{} ms", static_cast<double>(t.count()) / 1e6); }

// How far a boundary lies outside [lo, hi] (negative: inside, by how much).
Nanos outside(Nanos boundary, Nanos lo, Nanos hi) { return std::max(lo - boundary, boundary - hi); }

std::string unbracketed(const PhaseBisection& p) {
  const auto& probes = p.bisection.probes;
  const auto took = [](const DebounceProbe& q) { return q.accepted; };
  const std::string at = ms(p.start);
  if (std::all_of(probes.begin(), probes.end(), took))
    return fmt::format(
        "boundary not bracketed for pulses starting at {}: every probe accepted, the narrowest {} us", at,
        to_us(p.bisection.accepted));
  if (std::none_of(probes.begin(), probes.end(), took))
    return fmt::format(
        "boundary not bracketed for pulses starting at {}: every probe rejected, the widest {} us", at,
        to_us(p.bisection.rejected));
  return fmt::format("no single boundary for pulses starting at {}: {} us rejected, {} us accepted", at,
                     to_us(p.bisection.rejected), to_us(p.bisection.accepted));
}

} // namespace

CheckResult check_debounce(std::span<const PhaseBisection> phases, const DebounceSpec& spec) {
  CheckResult r;
  r.kind = "debounce";
  if (phases.empty()) {
    r.measurements.push_back(error(spec.name + ".boundary", "no probe was run"));
    return r;
  }
  const bool several = phases.size() > 1;
  for (const auto& p : phases)
    for (const auto& probe : p.bisection.probes)
      r.probes.push_back(
          rig::Probe{probe.width, probe.accepted, several ? std::optional(p.start) : std::nullopt});
  const Nanos lo = spec.filter - spec.tolerance;
  const Nanos hi = spec.filter + spec.tolerance;

  const auto open =
      std::find_if(phases.begin(), phases.end(), [](const auto& p) { return !p.bisection.bracketed; });
  if (open != phases.end()) {
    r.measurements.push_back(failure(spec.name + ".boundary", unbracketed(*open)));
  } else {
    // The worst phase: its boundary farthest outside (or least inside) the limits; the first on a tie.
    const PhaseBisection* worst = &phases.front();
    Nanos narrowest = worst->bisection.accepted;
    Nanos widest = worst->bisection.accepted;
    Nanos bracket{0};
    for (const auto& p : phases) {
      const Nanos b = p.bisection.accepted;
      if (outside(b, lo, hi) > outside(worst->bisection.accepted, lo, hi)) worst = &p;
      narrowest = std::min(narrowest, b);
      widest = std::max(widest, b);
      bracket = std::max(bracket, p.bisection.accepted - p.bisection.rejected);
    }
    const std::string over = several
                                 ? fmt::format("; over {} start phases the boundary ran from {} us to {} us",
                                               phases.size(), to_us(narrowest), to_us(widest))
                                 : std::string();
    r.measurements.push_back(measure_time(
        spec.name + ".boundary", worst->bisection.accepted, TimeUnit::Us, lo, hi,
        fmt::format("pulses starting at {}: {} us rejected, {} us accepted{}; filter {} us ± {} us",
                    ms(worst->start), to_us(worst->bisection.rejected), to_us(worst->bisection.accepted),
                    over, to_us(spec.filter), to_us(spec.tolerance))));
    r.measurements.push_back(
        measure_time(spec.name + ".resolution", bracket, TimeUnit::Us, std::nullopt, std::nullopt,
                     several ? "width of the widest final bracket" : "width of the final bracket"));
  }
  std::size_t misjudged = 0;
  std::string first = "every probe judged as the filter says";
  for (const auto& p : phases) {
    for (const auto& probe : p.bisection.probes) {
      // A pulse of exactly filter - tolerance may go either way; one of filter + tolerance must be taken.
      const bool wrong = (probe.accepted && probe.width < lo) || (!probe.accepted && probe.width >= hi);
      if (wrong && misjudged++ == 0) {
        first = fmt::format("a {} us pulse was {} (starting at {})", to_us(probe.width),
                            probe.accepted ? "accepted" : "rejected", ms(p.start));
      }
    }
  }
  r.measurements.push_back(
      measure(spec.name + ".misjudged", static_cast<double>(misjudged), "", std::nullopt, 0.0, first));
  return r;
}

CheckResult check_debounce(const Bisection& bisection, const DebounceSpec& spec) {
  const PhaseBisection one{Nanos{0}, bisection};
  return check_debounce(std::span(&one, 1), spec);
}

} // namespace hilrig::checks
