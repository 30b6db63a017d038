#pragma once
// Fault variants of the virtual ANS1: models that are wrong on purpose, so a campaign can
// show that its checks catch them. Selected by name from a campaign file.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace hilrig::models::ans1 {

enum class Variant : std::uint8_t {
  Correct,                  // "nominal": as specified
  LateOutputs,              // outputs reach the pins 100 us after the scan: throughput beyond spec
  AdvanceWrongSign,         // advances move edges later instead of earlier
  AdvanceWrongScale,        // advance counts twice what speed x time gives
  SetpointOffByOneAtWrap,   // a pair that wraps through zero turns off one count late
  SpeedFilterStuck,         // the speed value never updates (stays 0)
  OutputStuckOn,            // output 1 is on whatever its program says
  BrakeNeverFaults,         // the brake monitor never raises a start/stop overrun (ans1-host)
  DieProtectionNeverCounts, // die-protection checks never increment the fault counter (ans1-host)
};

struct VariantName {
  Variant variant;
  std::string_view name;
  std::string_view description;
};

inline constexpr std::array<VariantName, 9> kVariantNames{{
    {Variant::Correct, "nominal", "as specified"},
    {Variant::LateOutputs, "late_outputs",
     "outputs reach the pins 100 us after the scan (throughput beyond the 20 us spec)"},
    {Variant::AdvanceWrongSign, "advance_wrong_sign", "advances move edges later instead of earlier"},
    {Variant::AdvanceWrongScale, "advance_wrong_scale", "advance counts are twice speed x time"},
    {Variant::SetpointOffByOneAtWrap, "setpoint_off_by_one_at_wrap",
     "a pair wrapping through zero turns off one count late"},
    {Variant::SpeedFilterStuck, "speed_filter_stuck", "the speed value never updates (stays 0): no advances"},
    {Variant::OutputStuckOn, "output_stuck_on", "output 1 is always on"},
    {Variant::BrakeNeverFaults, "brake_never_faults", "the brake monitor never raises a start/stop overrun"},
    {Variant::DieProtectionNeverCounts, "die_check_never_counts",
     "die-protection checks never increment the fault counter"},
}};

[[nodiscard]] constexpr std::optional<Variant> variant_from_name(std::string_view name) {
  for (const auto& v : kVariantNames) {
    if (v.name == name) {
      return v.variant;
    }
  }
  return std::nullopt;
}

[[nodiscard]] constexpr std::string_view variant_name(Variant variant) {
  for (const auto& v : kVariantNames) {
    if (v.variant == variant) {
      return v.name;
    }
  }
  return "unknown";
}

// The output delay a late-outputs variant uses (well beyond the 20 us master throughput).
inline constexpr std::int64_t kLateOutputDelayUs = 100;

} // namespace hilrig::models::ans1
