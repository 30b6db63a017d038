#pragma once
// Reads a campaign file and checks it whole before anything runs: unknown keys, wrong
// types, wiring to pins the DUT lacks, checks or stimuli naming unwired lines, times out
// of order, unknown variants or check kinds. Any problem throws CampaignError
// ("file:line:column: key: what was expected").

#include <string>
#include <string_view>

#include "rig/campaign/campaign.hpp"

namespace hilrig::campaign {

// Reads the file at path (the name in messages is the path as given).
[[nodiscard]] Campaign load_campaign(const std::string& path);
// Parses campaign text; file_name is used in messages.
[[nodiscard]] Campaign parse_campaign(std::string_view text, const std::string& file_name);

} // namespace hilrig::campaign
