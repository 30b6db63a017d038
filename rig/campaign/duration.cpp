#include "rig/campaign/duration.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace hilrig::campaign {

std::optional<Nanos> parse_duration(std::string_view text) {
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
    if (ec != std::errc{} || end != number.data() + number.size() || !std::isfinite(value))
      return std::nullopt;
    const double ns = value * u.ns;
    if (std::fabs(ns) > 9.0e18) return std::nullopt;
    return Nanos{static_cast<std::int64_t>(std::llround(ns))};
  }
  return std::nullopt;
}

} // namespace hilrig::campaign
