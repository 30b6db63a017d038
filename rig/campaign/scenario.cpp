#include <algorithm>

#include "rig/campaign/campaign.hpp"

namespace hilrig::campaign {

const Wire* Scenario::wire_for_rig(std::string_view rig_line) const {
  const auto it =
      std::find_if(wiring.begin(), wiring.end(), [&](const Wire& w) { return w.rig == rig_line; });
  return it == wiring.end() ? nullptr : &*it;
}

const CheckSpec* Scenario::check(std::string_view check_name) const {
  const auto it =
      std::find_if(checks.begin(), checks.end(), [&](const CheckSpec& c) { return c.name == check_name; });
  return it == checks.end() ? nullptr : &*it;
}

const Scenario& Campaign::scenario_of(const RunSpec& run) const {
  if (run.fault && *run.fault < fault_points.size() && !fault_points[*run.fault].empty())
    return fault_points[*run.fault].at(run.point);
  return points.at(run.point);
}

} // namespace hilrig::campaign
