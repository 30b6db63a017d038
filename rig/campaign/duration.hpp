#pragma once
// Durations and instants in a campaign file are written with a unit: "250us", "10ms",
// "1.5s", "800ns". A bare number is refused: a missing unit is the commonest typo.

#include <optional>
#include <string>
#include <string_view>

#include "core/time.hpp"

namespace hilrig::campaign {

// The longest duration a text gives, either way: 9e18 ns (about 285 years; a 64-bit count of
// nanoseconds holds 292).
inline constexpr Nanos kMaxDurationText{9'000'000'000'000'000'000};

// The duration, or nullopt when the text is not a number followed by ns, us, ms or s, or is
// one longer than kMaxDurationText either way.
[[nodiscard]] std::optional<Nanos> parse_duration(std::string_view text);

// As parse_duration, but a number with a unit too long to hold ("1e400s",
// "99999999999999999999s") reads as kMaxDurationText (its negative when negative): it is a
// duration, out of every key's range, and the range check that follows names that range
// instead of calling it "not a duration". The campaign reader reads every duration this way.
[[nodiscard]] std::optional<Nanos> parse_duration_clamped(std::string_view text);

// The units a duration's text takes, in words for a message.
inline constexpr std::string_view kDurationUnits = "ns, us, ms or s";

// Why TEXT is not a duration parse_duration reads, in words for a message: a word after the
// number that is not a unit ("100h", "60min") is named as such, so is a missing unit or number;
// empty when TEXT is one (or is one too long to hold: a range names that).
[[nodiscard]] std::string duration_text_problem(std::string_view text);

} // namespace hilrig::campaign
