#include "models/pls2700/faults.hpp"

namespace hilrig::models::pls2700 {

std::optional<Fault> fault_from_name(std::string_view name) {
  for (const FaultName& f : kFaultNames) {
    if (f.name == name) {
      return f.fault;
    }
  }
  return std::nullopt;
}

std::string_view fault_name(Fault fault) { return kFaultNames[static_cast<std::size_t>(fault)].name; }

} // namespace hilrig::models::pls2700
