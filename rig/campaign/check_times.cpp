#include "rig/campaign/check_times.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace hilrig::campaign {

namespace {

const char* unit_of(double ns_per_unit) {
  return ns_per_unit == 1e3 ? "us" : ns_per_unit == 1e6 ? "ms" : "ns";
}

// The value's time in whole ns, rounded as checks::Table::time() rounds it.
double ns_of(const nlohmann::json& v, double ns_per_unit) {
  return std::round(v.get<double>() * ns_per_unit);
}

std::optional<CheckTimeProblem> after_end(const Scenario& s, const checks::ParamSpec& p,
                                          const nlohmann::json& v) {
  const double end = static_cast<double>(s.end.count());
  const nlohmann::json* late = nullptr;
  if (v.is_array()) {
    const auto it = std::find_if(v.begin(), v.end(),
                                 [&](const nlohmann::json& e) { return ns_of(e, p.instant_ns) > end; });
    if (it != v.end()) late = &*it;
  } else if (ns_of(v, p.instant_ns) > end) {
    late = &v;
  }
  if (late == nullptr) return std::nullopt;
  const char* unit = unit_of(p.instant_ns);
  return CheckTimeProblem{p.name,
                          fmt::format("a time within the run, 0 .. {} {} (campaign.end); {} {} is after it",
                                      end / p.instant_ns, unit, late->get<double>(), unit)};
}

// A word check judges the latest observation at or before at_ms: before the first read there
// is none.
std::optional<CheckTimeProblem> before_first_read(const Scenario& s, const nlohmann::json& table) {
  if (!table.contains("at_ms") || !table.contains("observation") || !table["observation"].is_string())
    return std::nullopt;
  const std::string& name = table["observation"].get_ref<const std::string&>();
  std::optional<Nanos> first;
  for (const HostAction& h : s.host)
    if (h.kind == HostAction::Kind::Read && h.name == name && (!first || h.at < *first)) first = h.at;
  if (!first) return std::nullopt; // an unknown observation is named by the reader
  const double at = table["at_ms"].get<double>();
  if (ns_of(table["at_ms"], 1e6) >= static_cast<double>(first->count())) return std::nullopt;
  return CheckTimeProblem{"at_ms",
                          fmt::format("a time at or after the first [[host]] read of \"{}\" ({} ms): "
                                      "no observation exists before it; {} ms is earlier",
                                      name, static_cast<double>(first->count()) / 1e6, at)};
}

// A shaft_move counts the steps after from_ms and up to to_ms (or campaign.end), in whole ns:
// a window with no instant in it can hold no step, and its limits would judge nothing.
std::optional<CheckTimeProblem> empty_step_window(const Scenario& s, const checks::CheckKind& kind,
                                                  const nlohmann::json& table) {
  if (kind.name != "shaft_move" || !table.contains("from_ms") || !table["from_ms"].is_number())
    return std::nullopt;
  const bool to_given = table.contains("to_ms") && table["to_ms"].is_number();
  const double from = ns_of(table["from_ms"], 1e6);
  const double to = to_given ? ns_of(table["to_ms"], 1e6) : static_cast<double>(s.end.count());
  if (from < to) return std::nullopt;
  return CheckTimeProblem{
      to_given ? "to_ms" : "from_ms",
      fmt::format(
          "a window with time in it: steps after from_ms ({} ms) and up to {} ({} ms) count, in whole "
          "ns, and this one holds none",
          table["from_ms"].get<double>(), to_given ? "to_ms" : "campaign.end", to / 1e6)};
}

} // namespace

std::optional<CheckTimeProblem> check_time_problem(const Scenario& s, const checks::CheckKind& kind,
                                                   const nlohmann::json& table) {
  for (const checks::ParamSpec& p : kind.params) {
    if (p.instant_ns == 0.0 || !table.contains(p.name)) continue;
    if (auto problem = after_end(s, p, table[p.name])) return problem;
  }
  if (auto problem = empty_step_window(s, kind, table)) return problem;
  return before_first_read(s, table);
}

} // namespace hilrig::campaign
