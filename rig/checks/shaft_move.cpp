#include "rig/checks/shaft_move.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

namespace hilrig::checks {

CheckResult check_shaft_move(std::span<const Edge> step, std::span<const Edge> dir,
                             const ShaftMoveSpec& spec) {
  CheckResult r;
  r.kind = "shaft_move";
  std::int64_t net = 0;
  std::int64_t count = 0;
  std::int64_t reversals = 0;
  Nanos last = spec.from;
  std::optional<Nanos> prev;
  int prev_dir = 0;
  Nanos shortest = Nanos::max();
  Nanos shortest_at{0};
  for (const Edge& e : step) {
    if (e.time <= spec.from) continue;
    if (e.time > spec.to) break;
    const int d = level_at(dir, e.time, spec.dir_initial) == Level::High ? 1 : -1;
    net += d;
    ++count;
    if (prev_dir != 0 && d != prev_dir) {
      ++reversals;
    } else if (prev && e.time - *prev < shortest) {
      shortest = e.time - *prev;
      shortest_at = e.time;
    }
    prev = e.time;
    prev_dir = d;
    last = e.time;
  }
  const TraceWindow window{spec.from, last};
  // No step in the window judges nothing but a net distance: a duration, speed or reversal
  // count of a shaft that never moved would pass a board that never moves. Only `steps`
  // (e.g. 0 +- 0: the shaft stands still) makes no step a measurement.
  const bool judged_nothing = count == 0 && !spec.steps;
  const auto nothing = [&](const char* what) {
    r.measurements.push_back(error(
        spec.name + "." + what,
        fmt::format("nothing judged: no step in the window ({} ns .. {} ns); give steps "
                    "(e.g. 0) to judge a shaft that stands still",
                    spec.from.count(),
                    spec.to == Nanos::max() ? std::string("end") : fmt::format("{}", spec.to.count()))));
  };
  if (spec.steps) {
    r.measurements.push_back(measure(
        spec.name + ".steps", static_cast<double>(net), "steps", *spec.steps - spec.steps_tolerance,
        *spec.steps + spec.steps_tolerance,
        fmt::format("net steps (CW +) after {} ns: {} steps counted", spec.from.count(), count), window));
  }
  if ((spec.duration_min || spec.duration_max) && judged_nothing) {
    nothing("duration");
  } else if (spec.duration_min || spec.duration_max) {
    r.measurements.push_back(measure_time(
        spec.name + ".duration", last - spec.from, TimeUnit::Ms, spec.duration_min, spec.duration_max,
        count == 0 ? std::string("no step in the window")
                   : fmt::format("from {} ns to the last step", spec.from.count()),
        window, last));
  }
  if (spec.peak_min || spec.peak_max) {
    if (judged_nothing) {
      nothing("peak_speed");
    } else if (shortest == Nanos::max() && !spec.peak_min) {
      // Only a ceiling, and no speed to hold against it: nothing judged, not a pass or a fail.
      r.measurements.push_back(
          error(spec.name + ".peak_speed",
                "nothing judged: fewer than two steps in one direction, no speed to hold "
                "against peak_max"));
    } else if (shortest == Nanos::max()) {
      r.measurements.push_back(
          failure(spec.name + ".peak_speed", "fewer than two steps in one direction: no speed", window));
    } else {
      r.measurements.push_back(measure(spec.name + ".peak_speed", 1e9 / static_cast<double>(shortest.count()),
                                       "steps/s", spec.peak_min, spec.peak_max,
                                       fmt::format("shortest step interval {} ns", shortest.count()),
                                       TraceWindow{shortest_at - shortest, shortest_at}, shortest_at));
    }
  }
  if (spec.reversals && judged_nothing) {
    nothing("reversals");
  } else if (spec.reversals) {
    r.measurements.push_back(measure(spec.name + ".reversals", static_cast<double>(reversals), "",
                                     *spec.reversals, *spec.reversals, "direction changes between steps",
                                     window));
  }
  if (spec.profile) r.expected_rate = expected_step_rate(*spec.profile);
  return r;
}

} // namespace hilrig::checks
