// The campaign reader on any bytes: a file it cannot run must end in a CampaignError (bad
// input, exit 2); any other exception, a crash, a leak or a hang is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "rig/campaign/campaign_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hilrig::campaign::parse_campaign(text, "fuzz.toml");
  } catch (const hilrig::campaign::CampaignError&) {}
  return 0;
}
