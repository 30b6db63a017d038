#include "rig/checks/shaft_move.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace hilrig::checks {

namespace {

// Where the shaft stands at the window's end, from the capture after the window's last step.
enum class MoveEnd { Complete, Running, Unknown };

} // namespace

CheckResult check_shaft_move(std::span<const Edge> step, std::span<const Edge> dir, const ShaftMoveSpec& spec,
                             std::optional<Nanos> end) {
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
  Nanos longest{0};          // the slowest step interval in one direction in the window
  std::optional<Nanos> next; // the shaft's first step after the window, in the capture
  Nanos before = spec.from;  // the shaft's last step up to the window's start, or the start
  for (const Edge& e : step) {
    if (e.time <= spec.from) {
      before = e.time;
      continue;
    }
    if (e.time > spec.to) {
      next = e.time;
      break;
    }
    const int d = level_at(dir, e.time, spec.dir_initial) == Level::High ? 1 : -1;
    net += d;
    ++count;
    if (prev_dir != 0 && d != prev_dir) {
      ++reversals; // the shaft stopped and turned: no step interval of a move
    } else if (prev) {
      longest = std::max(longest, e.time - *prev);
      if (e.time - *prev < shortest) {
        shortest = e.time - *prev;
        shortest_at = e.time;
      }
    }
    prev = e.time;
    prev_dir = d;
    last = e.time;
  }
  // The shaft's step interval while it moves: its slowest in one direction in the window (a
  // turn is a stop, e.g. a homing sequence's 2 s pause, seeds/003 L1327; one step: from the
  // shaft's step before it, or from the window's start), and with a profile at least the
  // Starting Speed's (the slowest a profile runs, seeds/003 L863, L1350). A next step within
  // one interval is the same move, still running at the window's end; still for twice that
  // (a ramp down may stretch its last intervals), the move is over; in between, or the
  // capture ending first, its end is not known.
  Nanos still = count == 1 ? last - before : longest;
  if (spec.profile && spec.profile->starting_speed > 0.0)
    still = std::max(still, Nanos{static_cast<std::int64_t>(std::ceil(1e9 / spec.profile->starting_speed))});
  const Nanos quiet = next ? *next - last : end.value_or(Nanos::max()) - last;
  const MoveEnd move_end = next && quiet <= still ? MoveEnd::Running
                           : quiet > 2 * still    ? MoveEnd::Complete
                                                  : MoveEnd::Unknown;
  const bool cut = move_end != MoveEnd::Complete;
  const std::string why =
      move_end == MoveEnd::Running
          ? fmt::format("the shaft was still stepping when the window ended at {} ns (next step at {} ns, "
                        "{} ns after the last, within its step interval of {} ns)",
                        spec.to.count(), next->count(), quiet.count(), still.count())
          : fmt::format("the shaft's last step at {} ns was followed by {} {} ns later, not twice its step "
                        "interval of {} ns: the move may not be over",
                        last.count(), next ? "a step" : "the run's end", quiet.count(), still.count());
  // What the cut left unknown: errors, unless something already failed for certain (a check
  // with an error is an error, and the board's fail must not read as "not judged").
  std::vector<std::string> unjudged;
  const auto not_judged = [&](const char* what) { unjudged.emplace_back(what); };
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
  // A cut move: a measurement judged against the limit more steps cannot undo (a longer, a
  // faster, a further move) counts only when it already fails.
  const auto only_a_fail = [&](Measurement m, const char* what) {
    if (m.outcome == Outcome::Fail) {
      m.detail += ", at least: " + why;
      r.measurements.push_back(std::move(m));
    } else {
      not_judged(what);
    }
  };
  if (spec.steps) {
    const double lo = *spec.steps - spec.steps_tolerance, hi = *spec.steps + spec.steps_tolerance;
    const std::string detail =
        fmt::format("net steps (CW +) after {} ns: {} steps counted", spec.from.count(), count);
    if (!cut || spec.to_given) {
      // A window the campaign closed counts its own steps (a stretch of a jog is whole).
      r.measurements.push_back(
          measure(spec.name + ".steps", static_cast<double>(net), "steps", lo, hi, detail, window));
    } else {
      // The run's end closed it: the move's distance, already past the band only on the side
      // the shaft was heading (a move does not turn back).
      only_a_fail(measure(spec.name + ".steps", static_cast<double>(net), "steps",
                          prev_dir < 0 ? std::optional<double>(lo) : std::nullopt,
                          prev_dir > 0 ? std::optional<double>(hi) : std::nullopt, detail, window),
                  "steps");
    }
  }
  if ((spec.duration_min || spec.duration_max) && judged_nothing) {
    nothing("duration");
  } else if ((spec.duration_min || spec.duration_max) && cut) {
    // A move still running lasts at least to its next step seen (or its last, when the run
    // ended): over duration_max that is already too long; otherwise it is not known.
    const Nanos at_least = (move_end == MoveEnd::Running ? *next : last) - spec.from;
    only_a_fail(measure_time(spec.name + ".duration", at_least, TimeUnit::Ms, std::nullopt, spec.duration_max,
                             fmt::format("from {} ns to a step at {} ns", spec.from.count(),
                                         (spec.from + at_least).count()),
                             window, spec.from + at_least),
                "duration");
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
    } else if (shortest == Nanos::max() && cut) {
      not_judged("peak_speed"); // no speed yet: the move may still make one
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
      const double speed = 1e9 / static_cast<double>(shortest.count());
      const auto peak = [&](std::optional<double> lo) {
        return measure(spec.name + ".peak_speed", speed, "steps/s", lo, spec.peak_max,
                       fmt::format("shortest step interval {} ns", shortest.count()),
                       TraceWindow{shortest_at - shortest, shortest_at}, shortest_at);
      };
      // Cut: a faster stretch may still come; only a speed already over peak_max is judged.
      if (cut) {
        only_a_fail(peak(std::nullopt), "peak_speed");
      } else {
        r.measurements.push_back(peak(spec.peak_min));
      }
    }
  }
  if (spec.reversals && judged_nothing) {
    nothing("reversals");
  } else if (spec.reversals) {
    Measurement m = measure(spec.name + ".reversals", static_cast<double>(reversals), "",
                            cut ? std::nullopt : spec.reversals, *spec.reversals,
                            "direction changes between steps", window);
    if (cut) {
      only_a_fail(std::move(m), "reversals"); // more may follow; only too many already is judged
    } else {
      r.measurements.push_back(std::move(m));
    }
  }
  if (!unjudged.empty()) {
    const auto failed = std::find_if(r.measurements.begin(), r.measurements.end(),
                                     [](const Measurement& m) { return m.outcome == Outcome::Fail; });
    if (failed != r.measurements.end()) {
      failed->detail += fmt::format("; not judged, the move cut: {}", fmt::join(unjudged, ", "));
    } else {
      for (const std::string& what : unjudged)
        r.measurements.push_back(error(spec.name + "." + what, "nothing judged: " + why));
    }
  }
  if (spec.profile) r.expected_rate = expected_step_rate(*spec.profile);
  return r;
}

} // namespace hilrig::checks
