// The registry of DUTs this build can simulate. A new adapter adds one line to
// dut_registry() below and its files to rig/duts/CMakeLists.txt.

#include <algorithm>
#include <stdexcept>

#include "rig/duts/amci4501_dut.hpp"
#include "rig/duts/ans1_adapter.hpp"
#include "rig/duts/dut.hpp"
#include "rig/duts/pls2700_dut.hpp"
#include "rig/duts/reference_pls.hpp"
#include "rig/duts/smd23e_dut.hpp"
#include "rig/duts/ssi7361_dut.hpp"

namespace hilrig::duts {

const char* to_string(ParamKind kind) {
  switch (kind) {
  case ParamKind::Integer:
    return "integer";
  case ParamKind::Number:
    return "number";
  case ParamKind::Duration:
    return "duration";
  case ParamKind::Boolean:
    return "boolean";
  case ParamKind::Text:
    return "string";
  }
  return "?";
}

ParamRange between(double min, double max) { return ParamRange{min, max, {}}; }
ParamRange between(Nanos min, Nanos max) {
  return ParamRange{static_cast<double>(min.count()), static_cast<double>(max.count()), {}};
}
ParamRange one_of(std::vector<std::string> choices) {
  ParamRange r;
  r.choices = std::move(choices);
  return r;
}

bool in_range(const ParamRange& range, const ParamValue& value) {
  const auto inside = [&](double v) { return v >= range.min && v <= range.max; };
  if (const auto* i = std::get_if<std::int64_t>(&value)) return inside(static_cast<double>(*i));
  if (const auto* d = std::get_if<double>(&value)) return inside(*d);
  if (const auto* n = std::get_if<Nanos>(&value)) return inside(static_cast<double>(n->count()));
  if (const auto* t = std::get_if<std::string>(&value))
    return range.choices.empty() ||
           std::find(range.choices.begin(), range.choices.end(), *t) != range.choices.end();
  return true;
}

const ParamValue& DutParams::at(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw std::out_of_range("no DUT parameter " + std::string(name));
  return it->second;
}
std::int64_t DutParams::integer(std::string_view name) const { return std::get<std::int64_t>(at(name)); }
double DutParams::number(std::string_view name) const { return std::get<double>(at(name)); }
Nanos DutParams::duration(std::string_view name) const { return std::get<Nanos>(at(name)); }
bool DutParams::boolean(std::string_view name) const { return std::get<bool>(at(name)); }
const std::string& DutParams::text(std::string_view name) const { return std::get<std::string>(at(name)); }

const PinInfo* DutInfo::pin(std::string_view pin_name) const {
  const auto it =
      std::find_if(pins.begin(), pins.end(), [&](const PinInfo& p) { return p.name == pin_name; });
  return it == pins.end() ? nullptr : &*it;
}

const ParamInfo* DutInfo::param(std::string_view param_name) const {
  const auto it =
      std::find_if(params.begin(), params.end(), [&](const ParamInfo& p) { return p.name == param_name; });
  return it == params.end() ? nullptr : &*it;
}

bool DutInfo::has_variant(std::string_view variant) const {
  return std::any_of(variants.begin(), variants.end(),
                     [&](const VariantInfo& v) { return v.name == variant; });
}

std::optional<std::size_t> DutInfo::fault_index(std::string_view fault_name) const {
  for (std::size_t i = 0; i < faults.size(); ++i)
    if (faults[i].name == fault_name) return i;
  return std::nullopt;
}

std::optional<std::size_t> DutInfo::panel_index(std::string_view action_name) const {
  for (std::size_t i = 0; i < panel.size(); ++i)
    if (panel[i].name == action_name) return i;
  return std::nullopt;
}

DutParams DutInfo::with_defaults(const std::map<std::string, ParamValue, std::less<>>& given) const {
  DutParams out;
  for (const ParamInfo& p : params) out.set(p.name, p.default_value);
  for (const auto& [param_name, value] : given) out.set(param_name, value);
  return out;
}

std::optional<ParamConflict>
DutInfo::params_conflict(const std::map<std::string, ParamValue, std::less<>>& given) const {
  if (!conflict) return std::nullopt;
  std::optional<ParamConflict> found = conflict(with_defaults(given));
  if (!found || found->keys.empty()) return found;
  const auto blamed = std::find_if(found->keys.begin(), found->keys.end(),
                                   [&](const std::string& key) { return given.contains(key); });
  if (blamed != found->keys.end()) std::rotate(found->keys.begin(), blamed, blamed + 1);
  return found;
}

const std::vector<DutInfo>& dut_registry() {
  static const std::vector<DutInfo> registry = [] {
    std::vector<DutInfo> r;
    r.push_back(reference_pls_info());
    r.push_back(ans1_info());
    r.push_back(ssi7361_info());
    r.push_back(amci4501_info());
    r.push_back(pls2700_info());
    r.push_back(smd23e_info());
    std::sort(r.begin(), r.end(), [](const DutInfo& a, const DutInfo& b) { return a.name < b.name; });
    return r;
  }();
  return registry;
}

const DutInfo* find_dut(std::string_view name) {
  const auto& r = dut_registry();
  const auto it = std::find_if(r.begin(), r.end(), [&](const DutInfo& d) { return d.name == name; });
  return it == r.end() ? nullptr : &*it;
}

} // namespace hilrig::duts
