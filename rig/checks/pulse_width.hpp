#pragma once
// Pulse width: every pulse of one level on a line lasts between a minimum and a maximum.

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "core/line.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

struct PulseWidthSpec {
  std::string name = "pulse";
  Level level = Level::High; // a pulse is an edge to `level` followed by an edge back
  std::optional<Nanos> min{};
  std::optional<Nanos> max{};
  std::size_t min_pulses = 1;
};

// Measurements: "<name>.count" (lower min_pulses), "<name>.shortest" (us, lower min),
// "<name>.longest" (us, upper max); windows are the pulses that set them. A pulse still
// open at `end` (the end of the run) is not counted, unless it is already longer than max:
// then it is the longest, at least (end - start), and fails. Fewer complete pulses than
// min_pulses only because the run ended inside one leaves `.count` an error (nothing judged):
// that pulse may still have closed in time.
[[nodiscard]] CheckResult check_pulse_width(std::span<const Edge> line, const PulseWidthSpec& spec,
                                            std::optional<Nanos> end = std::nullopt);

} // namespace hilrig::checks
