#pragma once
// A detection-power result written out: power.json (versioned, machine-readable), a plain
// text table (stdout) and an HTML page (power.html), all from the same rows.

#include <string>

#include "rig/power/power.hpp"

namespace hilrig::power {

inline constexpr int kPowerFormatVersion = 1;

[[nodiscard]] std::string to_power_json(const PowerResult& result);
[[nodiscard]] std::string to_power_text(const PowerResult& result);
[[nodiscard]] std::string to_power_html(const PowerResult& result);

} // namespace hilrig::power
