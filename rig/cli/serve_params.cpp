#include "rig/cli/serve_params.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "rig/campaign/duration.hpp"

namespace hilrig::cli {

namespace {

std::string range_text(const duts::ParamInfo& p) {
  if (p.kind == duts::ParamKind::Boolean) return "true or false";
  if (!p.range.choices.empty()) return fmt::format("one of {}", fmt::join(p.range.choices, ", "));
  if (std::isinf(p.range.min) && std::isinf(p.range.max))
    return std::string("any ") + duts::to_string(p.kind);
  if (p.kind == duts::ParamKind::Duration) return fmt::format("{} ns .. {} ns", p.range.min, p.range.max);
  return fmt::format("{} .. {}", p.range.min, p.range.max);
}

std::optional<duts::ParamValue> parse_value(const duts::ParamInfo& p, const std::string& text) {
  try {
    std::size_t used = 0;
    switch (p.kind) {
    case duts::ParamKind::Integer: {
      const long long v = std::stoll(text, &used, 0);
      if (used != text.size()) return std::nullopt;
      return duts::ParamValue{static_cast<std::int64_t>(v)};
    }
    case duts::ParamKind::Number: {
      const double v = std::stod(text, &used);
      if (used != text.size() || !std::isfinite(v)) return std::nullopt;
      return duts::ParamValue{v};
    }
    case duts::ParamKind::Duration: {
      const auto v = campaign::parse_duration(text);
      if (!v) return std::nullopt;
      return duts::ParamValue{*v};
    }
    case duts::ParamKind::Boolean:
      if (text == "true") return duts::ParamValue{true};
      if (text == "false") return duts::ParamValue{false};
      return std::nullopt;
    case duts::ParamKind::Text:
      return duts::ParamValue{text};
    }
  } catch (const std::exception&) { // stoll / stod: not a number, or out of range
  }
  return std::nullopt;
}

} // namespace

duts::DutParams serve_params(const duts::DutInfo& device, const std::vector<std::string>& key_values) {
  std::map<std::string, duts::ParamValue, std::less<>> given;
  for (const std::string& kv : key_values) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--param " + kv + ": expected KEY=VALUE");
    const std::string key = kv.substr(0, eq);
    const std::string text = kv.substr(eq + 1);
    const duts::ParamInfo* p = device.param(key);
    if (p == nullptr) {
      std::string names;
      for (const duts::ParamInfo& q : device.params) names += (names.empty() ? "" : ", ") + q.name;
      throw std::invalid_argument("--param " + key + ": " + device.name + " has no such parameter (" + names +
                                  ")");
    }
    const auto value = parse_value(*p, text);
    if (!value || !duts::in_range(p->range, *value))
      throw std::invalid_argument("--param " + key + "=" + text + ": valid: " + range_text(*p));
    given[key] = *value;
  }
  return device.with_defaults(given);
}

} // namespace hilrig::cli
