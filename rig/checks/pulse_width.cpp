#include "rig/checks/pulse_width.hpp"

#include <fmt/format.h>

namespace hilrig::checks {

CheckResult check_pulse_width(std::span<const Edge> line, const PulseWidthSpec& spec,
                              std::optional<Nanos> end) {
  CheckResult r;
  r.kind = "pulse_width";
  std::optional<TraceWindow> shortest;
  std::optional<TraceWindow> longest;
  std::size_t count = 0;
  bool in_pulse = false; // the line is at spec.level since `start`
  Nanos start{0};
  for (const Edge& e : line) {
    if (e.level == spec.level) {
      in_pulse = true;
      start = e.time;
    } else if (in_pulse) {
      const TraceWindow w{start, e.time};
      const Nanos width = w.end - w.begin;
      if (!shortest || width < shortest->end - shortest->begin) shortest = w;
      if (!longest || width > longest->end - longest->begin) longest = w;
      ++count;
      in_pulse = false;
    }
  }
  // A pulse the run ended inside is at least (end - start) long: over max it is already too
  // long, whatever its end would have been (an output stuck on must not pass).
  std::optional<TraceWindow> open_too_long;
  if (in_pulse && end && spec.max && *end - start > *spec.max) open_too_long = TraceWindow{start, *end};
  if (count == 0 && spec.min_pulses == 0 && !open_too_long) {
    r.measurements.push_back(error(
        spec.name + ".count", fmt::format("nothing judged: no complete {} pulse", level_name(spec.level))));
    return r;
  }
  if (in_pulse && !open_too_long && count < spec.min_pulses && count + 1 >= spec.min_pulses) {
    // Short of min_pulses only by the pulse the run ended inside: it may still close in time,
    // so the count is not known (nothing judged), not a missing edge.
    r.measurements.push_back(error(
        spec.name + ".count",
        fmt::format("nothing judged: {} complete {} pulses of {} wanted; the run ended inside one from {} ns "
                    "that may still complete",
                    count, level_name(spec.level), spec.min_pulses, start.count())));
  } else {
    r.measurements.push_back(
        measure(spec.name + ".count", static_cast<double>(count), "", static_cast<double>(spec.min_pulses),
                std::nullopt,
                count == 0 ? fmt::format("missing edge: no complete {} pulse", level_name(spec.level))
                           : fmt::format("{} {} pulses", count, level_name(spec.level))));
  }
  if (open_too_long) {
    const TraceWindow& w = *open_too_long;
    r.measurements.push_back(measure_time(
        spec.name + ".longest", w.end - w.begin, TimeUnit::Us, std::nullopt, spec.max,
        fmt::format(
            "longest {0} pulse: from {1} ns, still {0} at the end of the run ({2} ns): at least this long",
            level_name(spec.level), w.begin.count(), w.end.count()),
        w, w.end));
  }
  if (count == 0) return r;
  const auto pulse = [&](const char* what, const TraceWindow& w, std::optional<Nanos> lo,
                         std::optional<Nanos> hi) {
    r.measurements.push_back(measure_time(spec.name + "." + what, w.end - w.begin, TimeUnit::Us, lo, hi,
                                          fmt::format("{} {} pulse: {} ns to {} ns", what,
                                                      level_name(spec.level), w.begin.count(), w.end.count()),
                                          w, w.end));
  };
  pulse("shortest", *shortest, spec.min, std::nullopt);
  if (!open_too_long) pulse("longest", *longest, std::nullopt, spec.max);
  return r;
}

} // namespace hilrig::checks
