#pragma once
// Fault variants of the virtual 7361: models that are wrong on purpose, so a campaign can
// show that its checks catch them. Selected by name from a campaign file.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace hilrig::models::ssi7361 {

enum class Variant : std::uint8_t {
  Correct,             // "nominal": as specified
  GraySwapped,         // Data Type bit read inverted: binary taken as Gray, Gray as binary
  SampleWrongEdge,     // samples bit k at the falling edge F_k, before the slave shifted it out
  OffsetBeforeScaling, // DV = (x + LO) * MUL / DIV instead of x * MUL / DIV + LO
  RateNotUpdated,      // the Rate of Change word never refreshes (stays 0)
  ErrorOrderReversed,  // validates RUT, Preset, Scalars, Format: reports a later error first
};

struct VariantName {
  Variant variant;
  std::string_view name;
};

inline constexpr std::array<VariantName, 6> kVariantNames{{
    {Variant::Correct, "nominal"},
    {Variant::GraySwapped, "gray_swapped"},
    {Variant::SampleWrongEdge, "sample_wrong_edge"},
    {Variant::OffsetBeforeScaling, "offset_before_scaling"},
    {Variant::RateNotUpdated, "rate_not_updated"},
    {Variant::ErrorOrderReversed, "error_order_reversed"},
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

} // namespace hilrig::models::ssi7361
