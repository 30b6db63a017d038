#pragma once
// The measurement builder: the one place a check's value meets its limits. Every check
// builds its measurements here, so every limit is judged by rig::judge's one rule
// (inclusive; times in integer ns, everything else with one epsilon) and every outcome word
// comes from the same place.

#include <optional>
#include <string>

#include "core/time.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::checks {

using rig::Measurement;
using rig::Outcome;
using rig::TraceWindow;

// Exact decimal conversions: an integer count of ns divided once, so 20'000 ns is exactly 20.0 us.
[[nodiscard]] constexpr double to_us(Nanos t) { return static_cast<double>(t.count()) / 1e3; }
[[nodiscard]] constexpr double to_ms(Nanos t) { return static_cast<double>(t.count()) / 1e6; }

// A value that is not a time (counts, a word, a rate) judged against its limits.
[[nodiscard]] Measurement measure(std::string name, double value, std::string unit,
                                  std::optional<double> lower, std::optional<double> upper,
                                  std::string detail, std::optional<TraceWindow> window = std::nullopt,
                                  std::optional<Nanos> at = std::nullopt);

enum class TimeUnit { Us, Ms };

// A time judged exactly in ns against its limits; written in `unit` (us or ms).
[[nodiscard]] Measurement measure_time(std::string name, Nanos value, TimeUnit unit,
                                       std::optional<Nanos> lower, std::optional<Nanos> upper,
                                       std::string detail, std::optional<TraceWindow> window = std::nullopt,
                                       std::optional<Nanos> at = std::nullopt);

// A measurement that is a failure for a named reason (a missing edge, a missing word).
[[nodiscard]] Measurement failure(std::string name, std::string reason,
                                  std::optional<TraceWindow> window = {});
// A measurement that could not be taken (bad parameters, no such signal, nothing captured
// to judge): outcome Error. A check that judged nothing is an error, never a pass.
[[nodiscard]] Measurement error(std::string name, std::string reason);

} // namespace hilrig::checks
