#pragma once
// Fault variants of the virtual 4501, each breaking one documented behaviour so a campaign can
// show that its checks catch it. Selected by name from a campaign file.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace hilrig::models::amci4501 {

enum class Variant : std::uint8_t {
  Correct,               // "nominal": as specified
  LateOutputs,           // responds after Params::late_throughput, beyond the 125 us throughput
  X2Counting,            // decodes X2 instead of X4 (half the counts)
  TimeWrongUnit,         // time values in 10 us units instead of 1 us
  TimeOffByOne,          // time values one timer tick (1 us) long
  Mode4FilterIgnored,    // mode 4 Filter 1 and Filter 2 not applied
  NoResponseNeverRaised, // status bit 1 never set
};

struct VariantName {
  Variant variant;
  std::string_view name;
  std::string_view description; // what it does wrong (`hilrig list`)
};

inline constexpr std::array<VariantName, 7> kVariantNames{{
    {Variant::Correct, "nominal", "as specified"},
    {Variant::LateOutputs, "late_outputs",
     "responds (Cycle Output, results) after late_throughput, 250 us, beyond the 125 us throughput"},
    {Variant::X2Counting, "x2_counting", "decodes the encoder X2 instead of X4: half the counts"},
    {Variant::TimeWrongUnit, "time_wrong_unit", "time values counted in 10 us units instead of 1 us"},
    {Variant::TimeOffByOne, "time_off_by_one", "time values one timer tick (1 us) long"},
    {Variant::Mode4FilterIgnored, "mode4_filter_ignored", "mode 4 Filter 1 and Filter 2 not applied"},
    {Variant::NoResponseNeverRaised, "no_response_never_raised", "status bit 1 (No Response) never set"},
}};

[[nodiscard]] constexpr std::optional<Variant> variant_from_string(std::string_view name) {
  for (const auto& v : kVariantNames) {
    if (v.name == name) return v.variant;
  }
  return std::nullopt;
}

[[nodiscard]] constexpr std::string_view to_string(Variant variant) {
  for (const auto& v : kVariantNames) {
    if (v.variant == variant) return v.name;
  }
  return "unknown";
}

} // namespace hilrig::models::amci4501
