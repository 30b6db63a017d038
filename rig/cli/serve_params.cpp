#include "rig/cli/serve_params.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "rig/campaign/duration.hpp"
#include "rig/campaign/limits.hpp"

namespace hilrig::cli {

namespace {

// The whole text as a number of type T (from_chars: no leading space, nothing after it; a
// leading '+' as TOML allows), or nullopt.
template <typename T, typename... Base> std::optional<T> whole(std::string_view text, Base... base) {
  if (text.starts_with('+')) text.remove_prefix(1);
  T v{};
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v, base...);
  if (text.empty() || r.ec != std::errc{} || r.ptr != end) return std::nullopt;
  return v;
}

// The text as the parameter's kind, written as a campaign writes it: an integer in decimal (or
// hex after 0x, as TOML; "010" is ten, not octal 8), a finite number, a duration with its unit,
// true or false, a word. Else throws what a campaign's [dut.params] says of the same value
// (rig/campaign/limits.hpp), after `where`.
duts::ParamValue parse_value(const duts::ParamInfo& p, const std::string& text, const std::string& where) {
  const auto wrong_kind = [&] {
    return std::invalid_argument(where + ": expected " + campaign::kind_text(p.kind));
  };
  switch (p.kind) {
  case duts::ParamKind::Integer: {
    const bool hex = text.starts_with("0x") || text.starts_with("0X");
    const std::string_view digits = std::string_view(text).substr(hex ? 2 : 0);
    if (hex && (digits.empty() || std::isxdigit(static_cast<unsigned char>(digits.front())) == 0))
      throw wrong_kind(); // no sign after 0x
    const auto v = whole<std::int64_t>(digits, hex ? 16 : 10);
    if (!v) throw wrong_kind();
    return *v;
  }
  case duts::ParamKind::Number: {
    const auto v = whole<double>(text);
    if (!v) throw wrong_kind();
    if (!std::isfinite(*v)) throw std::invalid_argument(where + ": " + std::string(campaign::kNotFiniteText));
    return *v;
  }
  case duts::ParamKind::Duration: {
    // Too long to hold reads as the longest, so the range check names the range (as a campaign).
    const auto v = campaign::parse_duration_clamped(text);
    if (!v) throw wrong_kind();
    return *v;
  }
  case duts::ParamKind::Boolean:
    if (text != "true" && text != "false") throw wrong_kind();
    return text == "true";
  case duts::ParamKind::Text:
    break;
  }
  return text;
}

} // namespace

duts::DutParams serve_params(const duts::DutInfo& device, const std::vector<std::string>& key_values) {
  std::map<std::string, duts::ParamValue, std::less<>> given;
  std::map<std::string, std::string, std::less<>> texts; // as written, for the messages
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
    // The same words as a campaign's [dut.params] (rig/campaign/limits.hpp).
    const std::string where = "--param " + key + "=" + text;
    duts::ParamValue value = parse_value(*p, text, where);
    if (!duts::in_range(p->range, value))
      throw std::invalid_argument(where + ": " + campaign::param_range_text(device.name, *p));
    given[key] = std::move(value);
    texts[key] = text;
  }
  // Values each in range may still not go together (a rule across keys, DutInfo::conflict).
  if (const auto conflict = device.params_conflict(given)) {
    const std::string& key = conflict->keys.front();
    const auto text = texts.find(key);
    throw std::invalid_argument(
        (text != texts.end() ? "--param " + key + "=" + text->second : "--param " + key) + ": " +
        conflict->expected);
  }
  return device.with_defaults(given);
}

} // namespace hilrig::cli
