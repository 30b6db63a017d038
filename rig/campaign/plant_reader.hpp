#pragma once
// Reads the campaign's [plant] table into a PlantSpec: every parameter by name, finite
// and within its range, errors at the key's file:line:col like the rest of the parser.
// Internal to the parser (scenario_reader.cpp).

#include <optional>
#include <string>

#include <toml++/toml.h>

#include "rig/campaign/campaign.hpp"
#include "rig/campaign/plant_spec.hpp"

namespace hilrig::campaign {

// nullopt when the file has no [plant].
// wiring: the scenario's, already read (plant inputs are board outputs, the valve monitor a
// board input).
[[nodiscard]] std::optional<PlantSpec> read_plant(const std::string& file, const toml::table& root,
                                                  const std::vector<Wire>& wiring);

} // namespace hilrig::campaign
