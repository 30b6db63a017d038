#include "rig/checks/brake.hpp"

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
  CheckResult r;
  r.kind = "brake_stop_time";
  const auto still = standstill_after(motion, applied, trace_end);
  if (!still) {
    r.measurements.push_back(failure(spec.name + ".stop_time",
                                     "no standstill: the shaft was still moving when the trace ended",
                                     TraceWindow{applied, trace_end}));
    return r;
  }
  const Nanos stop = *still - applied;
  const double measured = to_ms(stop);
  const double limit = to_ms(spec.limit);
  r.measurements.push_back(measure_time(
      spec.name + ".stop_time", stop, TimeUnit::Ms, std::nullopt, spec.limit,
      fmt::format("brake applied at {} ns, standstill at {} ns", applied.count(), still->count()),
      TraceWindow{applied, *still}, *still));
  if (spec.reported_ms) {
    r.measurements.push_back(measure(spec.name + ".reported", *spec.reported_ms, "ms",
                                     measured - spec.report_tolerance_ms, measured + spec.report_tolerance_ms,
                                     fmt::format("board reported {} ms; measured {} ms ± {} ms",
                                                 *spec.reported_ms, measured, spec.report_tolerance_ms)));
  }
  if (spec.check_fault) {
    // Over the limit by the one comparison rule: the reported time (ms, a word) with its
    // epsilon, the measured time exactly in ns.
    const bool from_reported = spec.fault_from_reported && spec.reported_ms;
    const double basis = from_reported ? *spec.reported_ms : measured;
    const bool over = from_reported ? rig::judge(basis, std::nullopt, limit) == Outcome::Fail
                                    : rig::judge(stop, std::nullopt, spec.limit) == Outcome::Fail;
    const double expected = over ? 1.0 : 0.0;
    const auto e = next_edge(fault_output, applied, Nanos::max(), spec.fault_level);
    const double seen = e ? 1.0 : 0.0;
    r.measurements.push_back(measure(
        spec.name + ".fault_output", seen, "", expected, expected,
        fmt::format("stop time {} ms against limit {} ms: fault output {} expected, {}", basis, limit,
                    expected > 0.0 ? "asserted" : "not asserted",
                    e ? fmt::format("asserted at {} ns", e->time.count()) : std::string("never asserted")),
        e ? std::optional<TraceWindow>{TraceWindow{applied, e->time}} : std::nullopt,
        e ? std::optional<Nanos>{e->time} : std::nullopt));
  }
  return r;
}

} // namespace hilrig::checks
