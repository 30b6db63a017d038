#pragma once
// The programmed setup of one limit-switch output (command blocks 3, 5 and 6; spec §4.3-§4.8)
// and of the shift register (command block 9, §4.9). Plain structs: the host interface parses
// command blocks into them and the device applies them with Ans1::configure_output() and
// Ans1::configure_shift_register(). All positions are scaled counts 0..FSC-1.
#include <array>
#include <cstdint>

namespace hilrig::models::ans1 {

inline constexpr int kOutputCount = 16;
inline constexpr int kInputCount = 16;
inline constexpr int kPairsPerOutput = 4;
inline constexpr int kShiftRegisterBits = 256;

// One setpoint pair (CB3 words 4k..4k+3). From == To == 0 is an unused pair; From == To != 0
// is on at every position; From > To wraps through zero. Stitching is active when both
// stitch values are non-zero.
struct SetpointPair {
  std::uint16_t from = 0;
  std::uint16_t to = 0;
  std::uint16_t on_stitch = 0;
  std::uint16_t off_stitch = 0;
  [[nodiscard]] constexpr bool used() const { return from != 0 || to != 0; }
  [[nodiscard]] constexpr bool stitched() const { return on_stitch > 0 && off_stitch > 0; }
  friend bool operator==(const SetpointPair&, const SetpointPair&) = default;
};

// CB5 bits 9:8.
enum class AdvanceMode : std::uint8_t {
  None,     // no advance (deleted / never programmed)
  Fixed,    // 01: lead_ms on the From edge, trail_ms on the To edge
  Variable, // 10: lead_ms is the Fixed Advance (both edges), variable_us_per_rpm the VAT (From edge)
};

// CB5 bits 11:10 (the timer is disabled when timer_ms == 0).
enum class TimerType : std::uint8_t {
  TimeOrPosition, // 01: off at the first of {timer expired, To reached}
  TimeOnly,       // 1x: off when the timer expires; To is ignored
};

// CB6 words 2..17, one per input.
enum class AndingMode : std::uint8_t { None = 0, Simple = 1, Pulse = 2, Window = 3 };

struct OutputSetup {
  // CB3
  std::array<SetpointPair, kPairsPerOutput> pairs{};
  std::int32_t ls_offset = 0;        // LSO, -(FSC-1)..+(FSC-1); a LS preset recomputes it
  std::uint8_t ls_preset_input = 0;  // 0..16, 0 = none
  std::uint16_t ls_preset_value = 0; // LSPV, 0..FSC-1

  // CB5 advances (DA2 words 5, 6, 7)
  AdvanceMode advance_mode = AdvanceMode::None;
  std::uint16_t lead_ms = 0;             // Fixed mode: Lead Advance; Variable mode: Fixed Advance. 0..32767
  std::uint16_t trail_ms = 0;            // Fixed mode: Trail Advance. 0..32767
  std::uint16_t variable_us_per_rpm = 0; // Variable mode: VAT, 0..9999

  // CB5 timed limit (DA2 words 8, 9)
  TimerType timer_type = TimerType::TimeOrPosition;
  std::uint16_t timer_ms = 0; // 0 = no timer, else 1..32767

  // CB6 speed enabling: both 0 = not used; Low < High between; Low > High outside.
  std::int16_t rpm_low = 0;
  std::int16_t rpm_high = 0;

  // CB6 input ANDing (index 0 = input 1) and the window limits for a Window input.
  std::array<AndingMode, kInputCount> anding{};
  std::uint16_t window_low = 0;
  std::uint16_t window_high = 0;

  // CB6 shift-register enabling: bit number 1..256, 0 = not used.
  std::uint16_t sr_bit = 0;

  friend bool operator==(const OutputSetup&, const OutputSetup&) = default;
};

// CB9: the 256-bit shift register shared by all outputs.
struct ShiftRegisterSetup {
  std::uint8_t input = 0;        // 1..16; 0 = shift register disabled
  std::uint16_t window_from = 0; // sensing window [from, to), GMP
  std::uint16_t window_to = 0;
  std::uint16_t shift_position = 0; // GMP at which the register shifts, once per cycle
  friend bool operator==(const ShiftRegisterSetup&, const ShiftRegisterSetup&) = default;
};

} // namespace hilrig::models::ans1
