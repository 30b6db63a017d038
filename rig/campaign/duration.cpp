#include "rig/campaign/duration.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace hilrig::campaign {

namespace {

// What a duration's text holds: a duration, one too long to hold (with its sign), or none.
struct DurationText {
  std::optional<Nanos> value;
  int too_long = 0; // +1 or -1 when the number with its unit is beyond kMaxDurationText
};

DurationText read_duration(std::string_view text) {
  struct Unit {
    std::string_view suffix;
    double ns;
  };
  // "ms" and "us" before "s" so the longest suffix wins.
  constexpr Unit units[] = {{"ns", 1.0}, {"us", 1e3}, {"ms", 1e6}, {"s", 1e9}};
  for (const Unit& u : units) {
    if (text.size() <= u.suffix.size() || !text.ends_with(u.suffix)) continue;
    const std::string_view number = text.substr(0, text.size() - u.suffix.size());
    double value = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (end != number.data() + number.size()) return {};
    const int sign = number.starts_with('-') ? -1 : 1;
    if (ec == std::errc::result_out_of_range) {
      // Too large for a double ("1e400"), or too small ("1e-400": zero nanoseconds).
      const std::string copy(number);
      if (std::isinf(std::strtod(copy.c_str(), nullptr))) return {std::nullopt, sign};
      return {Nanos{0}, 0};
    }
    if (ec != std::errc{} || !std::isfinite(value)) return {};
    const double ns = value * u.ns;
    if (std::fabs(ns) > static_cast<double>(kMaxDurationText.count())) return {std::nullopt, sign};
    return {Nanos{static_cast<std::int64_t>(std::llround(ns))}, 0};
  }
  return {};
}

} // namespace

std::optional<Nanos> parse_duration(std::string_view text) { return read_duration(text).value; }

std::optional<Nanos> parse_duration_clamped(std::string_view text) {
  const DurationText d = read_duration(text);
  if (d.too_long != 0) return Nanos{d.too_long * kMaxDurationText.count()};
  return d.value;
}

std::string duration_text_problem(std::string_view text) {
  const DurationText d = read_duration(text);
  if (d.value || d.too_long != 0) return {};
  // The unit is the letters at the end; what comes before them is the number.
  std::size_t unit_at = text.size();
  while (unit_at > 0 && std::isalpha(static_cast<unsigned char>(text[unit_at - 1])) != 0) --unit_at;
  const std::string_view unit = text.substr(unit_at);
  const std::string_view number = text.substr(0, unit_at);
  if (unit.empty()) return fmt::format("no unit (one of {})", kDurationUnits);
  if (number.empty()) return fmt::format("no number before a unit ({})", kDurationUnits);
  if (unit != "ns" && unit != "us" && unit != "ms" && unit != "s")
    return fmt::format("\"{}\" is not a unit (one of {})", unit, kDurationUnits);
  return fmt::format("\"{}\" is not a finite number", number);
}

} // namespace hilrig::campaign
