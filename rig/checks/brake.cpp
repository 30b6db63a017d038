#include "rig/checks/brake.hpp"

#include "rig/checks/standstill.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace hilrig::checks {

void append_motion(std::vector<PositionSample>& motion, PositionSample sample) {
  motion.push_back(sample);
  const std::size_t n = motion.size();
  if (n < 3) return;
  if (motion[n - 2].position != sample.position) {
    // A new last change: earlier changes are older, so they cannot be the last one.
    motion[1] = motion[n - 2];
    motion[2] = sample;
    motion.resize(3);
    return;
  }
  // No change: the sample before is redundant unless it is the first or ends a change.
  if (motion[n - 3].position == motion[n - 2].position) motion.erase(motion.end() - 2);
}

std::optional<Nanos> standstill_after(std::span<const PositionSample> motion, Nanos from, Nanos trace_end) {
  Nanos still = from;
  for (std::size_t i = 1; i < motion.size(); ++i) {
    if (motion[i].position != motion[i - 1].position) still = std::max(still, motion[i].time);
  }
  const Nanos last = motion.empty() ? from : std::max(motion.back().time, trace_end);
  if (last <= still) return std::nullopt;
  return still;
}

CheckResult check_brake_stop(Nanos applied, std::span<const PositionSample> motion, Nanos trace_end,
                             std::span<const Edge> fault_output, const BrakeSpec& spec) {
  return check_brake_stop(applied, standstill_interval(motion, applied, trace_end), trace_end, fault_output,
                          spec);
}

CheckResult check_brake_stop(Nanos applied, std::optional<Standstill> still, Nanos trace_end,
                             std::span<const Edge> fault_output, const BrakeSpec& spec) {
  CheckResult r;
  r.kind = "brake_stop_time";
  if (!still) {
    // Stopped after trace_end, if at all: a stop time over trace_end - applied, which fails
    // for certain only once that reaches the limit (the one rule: limit itself passes).
    const Nanos seen = trace_end - applied;
    if (seen >= spec.limit)
      r.measurements.push_back(failure(
          spec.name + ".stop_time",
          fmt::format("no standstill: the shaft was still moving when the trace ended {} ms after the brake "
                      "applied at {} ns, over the {} ms limit",
                      to_ms(seen), applied.count(), to_ms(spec.limit)),
          TraceWindow{applied, trace_end}));
    else
      r.measurements.push_back(error(
          spec.name + ".stop_time",
          fmt::format(
              "nothing judged: the trace ended {} ms after the brake applied at {} ns, within the {} ms "
              "limit, before the shaft stood still (campaign.end cuts the stop)",
              to_ms(seen), applied.count(), to_ms(spec.limit))));
    return r;
  }
  const Nanos stop = still->latest - applied;
  const Nanos stop_earliest = still->earliest - applied;
  const double measured = to_ms(stop);
  const double earliest = to_ms(stop_earliest);
  const double limit = to_ms(spec.limit);
  const std::string where =
      still->exact()
          ? fmt::format("standstill at {} ns ({})", still->latest.count(),
                        still->rule.empty() ? std::string("from the motion") : still->rule)
          : fmt::format("standstill in [{}, {}] ns (last count change, + one count at the final speed "
                        "bound): stop time {} .. {} ms, judged on the upper end",
                        still->earliest.count(), still->latest.count(), earliest, measured);
  r.measurements.push_back(
      measure_time(spec.name + ".stop_time", stop, TimeUnit::Ms, std::nullopt, spec.limit,
                   fmt::format("brake applied at {} ns{}, {}", applied.count(),
                               spec.application.empty() ? "" : " (" + spec.application + ")", where),
                   TraceWindow{applied, still->latest}, still->latest));
  // With the board's tick: the window its report may lie in (plain values: no optional to
  // read through, which GCC cannot prove set).
  const bool windowed = spec.report_tick.has_value();
  const ReportWindow window =
      windowed ? report_window(applied, *still, *spec.report_tick, spec.applied_spread) : ReportWindow{};
  if (spec.reported_ms && windowed) {
    r.measurements.push_back(measure(
        spec.name + ".reported", *spec.reported_ms, "ms", window.low_ms, window.high_ms,
        fmt::format("board reported {} ms; a correct board with a {} ms stop timer tick reports within "
                    "[{}, {}] ms: from the {} ({} ns) - 1 tick to the standstill ({} ns) + "
                    "1 tick, after the brake applied at {} ns",
                    *spec.reported_ms, to_ms(*spec.report_tick), window.low_ms, window.high_ms,
                    still->rule.empty() ? std::string("last count change") : "standstill by " + still->rule,
                    still->last_change().count(), still->latest.count(), applied.count())));
  } else if (spec.reported_ms) {
    r.measurements.push_back(measure(spec.name + ".reported", *spec.reported_ms, "ms",
                                     earliest - spec.report_tolerance_ms, measured + spec.report_tolerance_ms,
                                     fmt::format("board reported {} ms; measured {} ms ± {} ms",
                                                 *spec.reported_ms, measured, spec.report_tolerance_ms)));
  }
  if (spec.check_fault) {
    // Over the limit by the one comparison rule: the reported time (ms, a word) with its
    // epsilon, the measured time exactly in ns. From an interval that straddles the limit,
    // either answer of the board is right; so from a report window (the board decides from
    // its own report) that straddles it.
    const bool from_reported = spec.fault_from_reported && spec.reported_ms;
    const auto over_ms = [&](double ms) { return rig::judge(ms, std::nullopt, limit) == Outcome::Fail; };
    const auto over = [&](Nanos t) {
      return from_reported ? over_ms(*spec.reported_ms)
                           : rig::judge(t, std::nullopt, spec.limit) == Outcome::Fail;
    };
    const double high = from_reported ? *spec.reported_ms : measured;
    const bool by_window = windowed && !from_reported;
    const double expected_low = (by_window ? over_ms(window.low_ms) : over(stop_earliest)) ? 1.0 : 0.0;
    const double expected_high = (by_window ? over_ms(window.high_ms) : over(stop)) ? 1.0 : 0.0;
    const auto e = next_edge(fault_output, applied, Nanos::max(), spec.fault_level);
    const double seen = e ? 1.0 : 0.0;
    r.measurements.push_back(measure(
        spec.name + ".fault_output", seen, "", expected_low, expected_high,
        fmt::format("{} against limit {} ms: fault output {} expected, {}",
                    by_window ? fmt::format("a report in [{}, {}] ms", window.low_ms, window.high_ms)
                              : fmt::format("stop time {} ms", high),
                    limit,
                    expected_low == expected_high ? (expected_high > 0.0 ? "asserted" : "not asserted")
                                                  : "either",
                    e ? fmt::format("asserted at {} ns", e->time.count()) : std::string("never asserted")),
        e ? std::optional<TraceWindow>{TraceWindow{applied, e->time}} : std::nullopt,
        e ? std::optional<Nanos>{e->time} : std::nullopt));
  }
  return r;
}

ReportWindow report_window(Nanos applied, const Standstill& still, Nanos tick, Nanos applied_spread) {
  const Nanos low = std::max(still.last_change(), applied) - applied - applied_spread - tick;
  const Nanos high = std::max(still.latest, applied) - applied + tick;
  return ReportWindow{to_ms(low), to_ms(high)};
}

} // namespace hilrig::checks
