// The rig config reader (docs/rig-config.md) on any bytes: bad input is a CampaignError,
// anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "rig/hardware/rig_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hilrig::hardware::parse_rig_config(text, "fuzz-rig.toml");
  } catch (const hilrig::campaign::CampaignError&) {}
  return 0;
}
