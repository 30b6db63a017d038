#include "rig/campaign/check_selection.hpp"

#include <algorithm>
#include <set>

namespace hilrig::campaign {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

bool selected(const CheckSpec& c, const CheckSelection& s) {
  if (contains(s.only, c.name)) return true;
  return std::any_of(c.tags.begin(), c.tags.end(), [&](const std::string& t) { return contains(s.tags, t); });
}

void keep_selected(Scenario& s, const CheckSelection& selection) {
  std::erase_if(s.checks, [&](const CheckSpec& c) { return !selected(c, selection); });
}

} // namespace

std::vector<std::string> check_names(const Campaign& c) {
  std::set<std::string> names;
  for (const Scenario& s : c.points)
    for (const CheckSpec& k : s.checks) names.insert(k.name);
  return {names.begin(), names.end()};
}

std::vector<std::string> check_tags(const Campaign& c) {
  std::set<std::string> tags;
  for (const Scenario& s : c.points)
    for (const CheckSpec& k : s.checks) tags.insert(k.tags.begin(), k.tags.end());
  return {tags.begin(), tags.end()};
}

std::size_t select_checks(Campaign& c, const CheckSelection& selection) {
  if (selection.all()) return c.points.empty() ? 0 : c.points.front().checks.size();
  for (Scenario& s : c.points) keep_selected(s, selection);
  for (auto& points : c.fault_points)
    for (Scenario& s : points) keep_selected(s, selection);
  const std::vector<std::string> kept = check_names(c);
  std::vector<FaultSpec> faults;
  std::vector<std::vector<Scenario>> fault_points;
  for (std::size_t f = 0; f < c.faults.size(); ++f) {
    auto& by = c.faults[f].caught_by;
    std::erase_if(by, [&](const std::string& n) { return !contains(kept, n); });
    if (by.empty()) continue;
    faults.push_back(std::move(c.faults[f]));
    fault_points.push_back(std::move(c.fault_points[f]));
  }
  c.faults = std::move(faults);
  c.fault_points = std::move(fault_points);
  c.runs = plan_runs(c, c.seed);
  return c.points.empty() ? 0 : c.points.front().checks.size();
}

} // namespace hilrig::campaign
