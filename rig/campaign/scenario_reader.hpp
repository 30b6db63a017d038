#pragma once
// Reads one scenario point of a campaign file (every section but [[sweep]]) and checks
// it whole. Internal to the parser: campaign_parser.cpp calls it once per sweep point.

#include <string>

#include <toml++/toml.h>

#include "rig/campaign/campaign.hpp"

namespace hilrig::campaign {

struct ScenarioFile {
  std::string name;
  std::string description;
  std::uint64_t seed = 1;
  std::int64_t repeat = 1;
  Scenario scenario;
  std::vector<FaultSpec> faults;
};

[[nodiscard]] ScenarioFile read_scenario_file(const std::string& file, const toml::table& root);

// The rig lines the encoder drives.
inline constexpr std::string_view kEncoderA = "enc.A";
inline constexpr std::string_view kEncoderB = "enc.B";
[[nodiscard]] inline bool is_encoder_line(std::string_view rig) {
  return rig == kEncoderA || rig == kEncoderB;
}

} // namespace hilrig::campaign
