#include "rig/checks/measure.hpp"

#include <cmath>
#include <utility>

namespace hilrig::checks {

Measurement measure(std::string name, double value, std::string unit, std::optional<double> lower,
                    std::optional<double> upper, std::string detail, std::optional<TraceWindow> window,
                    std::optional<Nanos> at) {
  Measurement m;
  m.name = std::move(name);
  m.value = value;
  m.unit = std::move(unit);
  m.lower = lower;
  m.upper = upper;
  m.outcome = rig::judge(value, lower, upper);
  // The reason a value or limit judged nothing (judge(): Error) leads the sentence.
  const auto finite = [](std::optional<double> v) { return !v || std::isfinite(*v); };
  if (std::isnan(value))
    m.detail = "not a number: " + detail;
  else if (!std::isfinite(value))
    m.detail = "not a finite number: " + detail;
  else if (!finite(lower) || !finite(upper))
    m.detail = "a limit is not a finite number: " + detail;
  else
    m.detail = std::move(detail);
  m.window = window;
  m.at = at;
  return m;
}

Measurement measure_time(std::string name, Nanos value, TimeUnit unit, std::optional<Nanos> lower,
                         std::optional<Nanos> upper, std::string detail, std::optional<TraceWindow> window,
                         std::optional<Nanos> at) {
  const auto shown = [unit](Nanos t) { return unit == TimeUnit::Us ? to_us(t) : to_ms(t); };
  const auto shown_opt = [&](std::optional<Nanos> t) {
    return t ? std::optional<double>{shown(*t)} : std::nullopt;
  };
  Measurement m;
  m.name = std::move(name);
  m.value = shown(value);
  m.unit = unit == TimeUnit::Us ? "us" : "ms";
  m.lower = shown_opt(lower);
  m.upper = shown_opt(upper);
  m.outcome = rig::judge(value, lower, upper);
  m.detail = std::move(detail);
  m.window = window;
  m.at = at;
  return m;
}

Measurement failure(std::string name, std::string reason, std::optional<TraceWindow> window) {
  Measurement m;
  m.name = std::move(name);
  m.outcome = Outcome::Fail;
  m.detail = std::move(reason);
  m.window = window;
  return m;
}

Measurement error(std::string name, std::string reason) {
  Measurement m;
  m.name = std::move(name);
  m.outcome = Outcome::Error;
  m.detail = std::move(reason);
  return m;
}

} // namespace hilrig::checks
