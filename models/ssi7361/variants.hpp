#pragma once
// Fault variants of the virtual 7361, each breaking one documented behaviour so a campaign can
// show that its checks catch it. Selected by name from a campaign file.

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
  RateFromPowerUp,     // the first rate update measures the jump from DV 0 to the first frame
};

struct VariantName {
  Variant variant;
  std::string_view name;
  std::string_view description; // what it does wrong (`hilrig list`)
};

inline constexpr std::array<VariantName, 7> kVariantNames{{
    {Variant::Correct, "nominal", "as specified"},
    {Variant::GraySwapped, "gray_swapped",
     "Data Type bit read inverted: binary frames decoded as Gray and Gray as binary"},
    {Variant::SampleWrongEdge, "sample_wrong_edge",
     "samples bit k at the falling clock edge, before the transducer shifted it out (reads the previous "
     "bit)"},
    {Variant::OffsetBeforeScaling, "offset_before_scaling",
     "Data Value = (x + offset) x MUL / DIV instead of x x MUL / DIV + offset"},
    {Variant::RateNotUpdated, "rate_not_updated",
     "the Rate of Change word never refreshes (stays 0, no ROVErr)"},
    {Variant::ErrorOrderReversed, "error_order_reversed",
     "checks RUT, Preset, Scalars, Format in reverse order: a later parameter's error is reported first"},
    {Variant::RateFromPowerUp, "rate_from_power_up",
     "the first rate update after power-up measures the jump from 0 to the first frame's Data Value: "
     "a huge rate and a false ROVErr with no motion"},
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
