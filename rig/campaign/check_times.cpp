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

// A window (from, to] of whole ns that a check scans for its stimulus: a shaft_move's steps
// after from_ms and up to to_ms, a throughput scan's setpoint crossings after from_us and up
// to to_us. From 0 to campaign.end by default.
struct ScanWindow {
  const char* kind;
  const char* from;
  const char* to;
  double ns_per_unit;
  const char* what; // what the window holds
};
constexpr ScanWindow kScanWindows[] = {{"shaft_move", "from_ms", "to_ms", 1e6, "steps"},
                                       {"throughput", "from_us", "to_us", 1e3, "setpoint crossings"}};

// A window with no instant in it holds no stimulus, and its limits would judge nothing.
std::optional<CheckTimeProblem> empty_scan_window(const Scenario& s, const checks::CheckKind& kind,
                                                  const nlohmann::json& table) {
  for (const ScanWindow& w : kScanWindows) {
    if (kind.name != w.kind) continue;
    const bool from_given = table.contains(w.from) && table[w.from].is_number();
    const bool to_given = table.contains(w.to) && table[w.to].is_number();
    if (!from_given && !to_given) continue;
    const double from = from_given ? ns_of(table[w.from], w.ns_per_unit) : 0.0;
    const double to = to_given ? ns_of(table[w.to], w.ns_per_unit) : static_cast<double>(s.end.count());
    if (from < to) continue;
    const char* unit = unit_of(w.ns_per_unit);
    return CheckTimeProblem{
        to_given ? w.to : w.from,
        fmt::format("a window with time in it: {} after {} ({} {}) and up to {} ({} {}) count, in whole "
                    "ns, and this one holds none",
                    w.what, from_given ? w.from : "the run's start",
                    from_given ? table[w.from].get<double>() : 0.0, unit, to_given ? w.to : "campaign.end",
                    to / w.ns_per_unit, unit)};
  }
  return std::nullopt;
}

} // namespace

std::optional<CheckTimeProblem> check_time_problem(const Scenario& s, const checks::CheckKind& kind,
                                                   const nlohmann::json& table) {
  for (const checks::ParamSpec& p : kind.params) {
    if (p.instant_ns == 0.0 || !table.contains(p.name)) continue;
    if (auto problem = after_end(s, p, table[p.name])) return problem;
  }
  if (auto problem = empty_scan_window(s, kind, table)) return problem;
  return before_first_read(s, table);
}

} // namespace hilrig::campaign
