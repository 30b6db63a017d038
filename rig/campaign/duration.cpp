#include "rig/campaign/duration.hpp"

#include <charconv>
#include <cmath>
#include <string>

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

} // namespace hilrig::campaign
