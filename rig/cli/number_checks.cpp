#include "rig/cli/number_checks.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace hilrig::cli {
namespace {

// The whole text as a finite number, or NaN.
double number_in(const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  return r.ec == std::errc{} && r.ptr == end && std::isfinite(v) ? v : std::nan("");
}

// A number above zero (`inclusive`: or zero).
CLI::Validator above_zero(bool inclusive) {
  const std::string rule = inclusive ? ">= 0" : "> 0";
  return CLI::Validator(
      [inclusive, rule](std::string& text) -> std::string {
        const double v = number_in(text);
        if (std::isnan(v)) return text + " is not a number";
        if (inclusive ? v >= 0.0 : v > 0.0) return {};
        return text + " is not " + rule;
      },
      "NUMBER " + rule);
}

} // namespace

CLI::Validator positive_number() { return above_zero(false); }
CLI::Validator non_negative_number() { return above_zero(true); }

} // namespace hilrig::cli
