#pragma once
// What the module stores in nvRAM: per channel Scale Factor, Circular Offset, tach response,
// (2742-18) Cycle Length and input trigger; Output Allocation; per output advances and up to
// eight ON/OFF pairs; the output mask and the keyboard lock.
#include <array>
#include <cstdint>

namespace hilrig::models::pls2700 {

inline constexpr int kOutputCount = 8;
inline constexpr int kMaxPairs = 8;
inline constexpr int kMaxAdvanceMs = 99;

// 2742-18 Input Polarity / Output Trigger byte (L1498-L1508).
enum class Trigger : std::uint8_t {
  PositiveEdge = 0,
  PositiveLevel = 1,
  NegativeEdge = 2,
  NegativeLevel = 3
};

struct ChannelSetup {
  int scale_factor = 360;  // R-SF-1 default
  int circular_offset = 0; // R-CO-1
  int tach_code = 3;       // R-T-1: 240 ms, 1 RPM
  int cycle_length = 360;  // 2742-18 (L1536)
  Trigger trigger = Trigger::PositiveEdge;
};

struct SetpointPair {
  int on = 0;
  int off = 0;
  friend bool operator==(const SetpointPair&, const SetpointPair&) = default;
};

struct OutputSetup {
  int advance_on_ms = 0;
  int advance_off_ms = 0;
  int pair_count = 0; // 0: no window programmed
  std::array<SetpointPair, kMaxPairs> pairs{};
};

struct Setup {
  std::array<ChannelSetup, 2> channels{};
  int output_allocation = 8; // R-OA-1: outputs 1..N follow channel 1
  std::array<OutputSetup, kOutputCount> outputs{};
  std::uint8_t mask = 0xFF;
  bool keyboard_disabled = false;
};

} // namespace hilrig::models::pls2700
