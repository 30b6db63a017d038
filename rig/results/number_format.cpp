#include "rig/results/number_format.hpp"

#include <cmath>
#include <fmt/format.h>

namespace hilrig::rig {

std::string format_number(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "NaN" : (v > 0 ? "∞" : "-∞");
  std::string s = fmt::format("{:.9g}", v);
  if (s == "-0") s = "0";
  return s;
}

std::string format_ns(double ns) {
  const double a = std::abs(ns);
  if (a >= 1e9) return format_number(ns / 1e9) + " s";
  if (a >= 1e6) return format_number(ns / 1e6) + " ms";
  if (a >= 1e3) return format_number(ns / 1e3) + " µs";
  return format_number(ns) + " ns";
}

std::string format_value(double v, const std::string& unit, const std::optional<double>& beside) {
  const std::string number = beside ? format_number_apart(v, beside, 9) : format_number(v);
  if (unit.empty()) return number;
  return number + " " + (unit == "us" ? std::string("µs") : unit);
}

std::optional<double> limit_beyond(double v, const std::optional<double>& lower,
                                   const std::optional<double>& upper) {
  if (upper && v > *upper) return upper;
  if (lower && v < *lower) return lower;
  return std::nullopt;
}

std::string format_number_apart(double v, const std::optional<double>& beside, int digits) {
  if (!std::isfinite(v)) return format_number(v);
  if (beside && *beside != v)
    while (digits < 17 && fmt::format("{:.{}g}", v, digits) == fmt::format("{:.{}g}", *beside, digits))
      ++digits;
  return fmt::format("{:.{}g}", v, digits);
}

} // namespace hilrig::rig
