#pragma once
// Fault variants of the virtual 4501: models that are wrong on purpose, so a campaign can
// show that its checks catch them. Selected by name from a campaign file.

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
};

inline constexpr std::array<VariantName, 7> kVariantNames{{
    {Variant::Correct, "nominal"},
    {Variant::LateOutputs, "late_outputs"},
    {Variant::X2Counting, "x2_counting"},
    {Variant::TimeWrongUnit, "time_wrong_unit"},
    {Variant::TimeOffByOne, "time_off_by_one"},
    {Variant::Mode4FilterIgnored, "mode4_filter_ignored"},
    {Variant::NoResponseNeverRaised, "no_response_never_raised"},
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
