#include "rig/campaign/limits.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace hilrig::campaign {

std::string duration_text(Nanos d) {
  struct Unit {
    std::int64_t ns;
    const char* suffix;
  };
  constexpr Unit units[] = {{1'000'000'000, "s"}, {1'000'000, "ms"}, {1'000, "us"}};
  for (const Unit& u : units)
    if (d.count() != 0 && d.count() % u.ns == 0) return fmt::format("{}{}", d.count() / u.ns, u.suffix);
  return d.count() == 0 ? std::string("0s") : fmt::format("{}ns", d.count());
}

bool is_label(const std::string& text) {
  return !text.empty() && text.size() <= limits::kMaxLabel &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c <= 0x7E; });
}

std::string label_range() { return fmt::format("1 .. {} printable ASCII characters", limits::kMaxLabel); }

std::string range_text(duts::ParamKind kind, const duts::ParamRange& range) {
  if (kind == duts::ParamKind::Text) {
    std::string words;
    for (const auto& c : range.choices) words += (words.empty() ? "" : ", ") + c;
    return words.empty() ? std::string("any text") : "one of " + words;
  }
  if (kind == duts::ParamKind::Boolean) return "true or false";
  const auto bound = [&](double v) {
    if (kind == duts::ParamKind::Duration) return duration_text(Nanos{static_cast<std::int64_t>(v)});
    return fmt::format("{}", v);
  };
  return fmt::format("{} .. {}", bound(range.min), bound(range.max));
}

std::string kind_text(duts::ParamKind kind) {
  switch (kind) {
  case duts::ParamKind::Integer:
    return "an integer";
  case duts::ParamKind::Number:
    return "a number";
  case duts::ParamKind::Duration: // a bare number is refused (duration.hpp): say why
    return R"(a duration with a unit, like "250us", "10ms" or "1.5s")";
  case duts::ParamKind::Boolean:
    return "true or false";
  case duts::ParamKind::Text:
    return "a string";
  }
  return "a value";
}

std::string param_range_text(std::string_view device, const duts::ParamInfo& param) {
  return fmt::format("{}{} ({} {})", param.kind == duts::ParamKind::Text ? "" : "a value in ",
                     range_text(param.kind, param.range), device, param.description);
}

} // namespace hilrig::campaign
