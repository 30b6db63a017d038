#pragma once
// Durations and instants in a campaign file are written with a unit: "250us", "10ms",
// "1.5s", "800ns". A bare number is refused: a missing unit is the commonest typo.

#include <optional>
#include <string_view>

#include "core/time.hpp"

namespace hilrig::campaign {

// The duration, or nullopt when the text is not a number followed by ns, us, ms or s.
[[nodiscard]] std::optional<Nanos> parse_duration(std::string_view text);

} // namespace hilrig::campaign
