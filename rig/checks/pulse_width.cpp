#include "rig/checks/pulse_width.hpp"

#include <fmt/format.h>

namespace hilrig::checks {

CheckResult check_pulse_width(std::span<const Edge> line, const PulseWidthSpec& spec) {
  CheckResult r;
  r.kind = "pulse_width";
  std::optional<TraceWindow> shortest;
  std::optional<TraceWindow> longest;
  std::size_t count = 0;
  std::optional<Nanos> start;
  for (const Edge& e : line) {
    if (e.level == spec.level) {
      start = e.time;
    } else if (start) {
      const TraceWindow w{*start, e.time};
      const Nanos width = w.end - w.begin;
      if (!shortest || width < shortest->end - shortest->begin) shortest = w;
      if (!longest || width > longest->end - longest->begin) longest = w;
      ++count;
      start.reset();
    }
  }
  if (count == 0 && spec.min_pulses == 0) {
    r.measurements.push_back(error(
        spec.name + ".count", fmt::format("nothing judged: no complete {} pulse", level_name(spec.level))));
    return r;
  }
  r.measurements.push_back(
      measure(spec.name + ".count", static_cast<double>(count), "", static_cast<double>(spec.min_pulses),
              std::nullopt,
              count == 0 ? fmt::format("missing edge: no complete {} pulse", level_name(spec.level))
                         : fmt::format("{} {} pulses", count, level_name(spec.level))));
  if (count == 0) return r;
  const auto pulse = [&](const char* what, const TraceWindow& w, std::optional<Nanos> lo,
                         std::optional<Nanos> hi) {
    r.measurements.push_back(measure_time(spec.name + "." + what, w.end - w.begin, TimeUnit::Us, lo, hi,
                                          fmt::format("{} {} pulse: {} ns to {} ns", what,
                                                      level_name(spec.level), w.begin.count(), w.end.count()),
                                          w, w.end));
  };
  pulse("shortest", *shortest, spec.min, std::nullopt);
  pulse("longest", *longest, std::nullopt, spec.max);
  return r;
}

} // namespace hilrig::checks
