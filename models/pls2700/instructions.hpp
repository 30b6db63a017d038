#pragma once
// The BTW command set (pls2700.md §5.3, §5.4): one instruction = a command word and its BCD
// data words. An instruction is validated completely, field by field in data order, before
// anything is applied: a rejected instruction changes nothing (L1340).
#include <cstddef>
#include <cstdint>
#include <span>

#include "models/pls2700/model_variant.hpp"
#include "models/pls2700/setup.hpp"

namespace hilrig::models::pls2700 {

inline constexpr std::uint16_t kDisableKeyboard = 0x8100;
inline constexpr std::uint16_t kEnableKeyboard = 0x8200;
inline constexpr std::uint16_t kSetMask = 0x8300; // | mask
inline constexpr std::uint16_t kClearErrors = 0x8400;
inline constexpr std::uint16_t kSetupChannel1 = 0x8800; // | bits
inline constexpr std::uint16_t kSetupChannel2 = 0x9800;
inline constexpr std::uint16_t kSetupBoth = 0xA800;
inline constexpr std::uint16_t kLimitSwitch = 0xC000; // | output << 4 | pairs

// Digit Y of the setup commands (reconstructed from 8801h, 8806h, A807h, digest §5.3).
inline constexpr unsigned kSetupSf = 0x1;
inline constexpr unsigned kSetupCo = 0x2;
inline constexpr unsigned kSetupTr = 0x4;
inline constexpr unsigned kSetupCl = 0x8; // 2742-18 only

enum class InstructionKind : std::uint8_t {
  Invalid,
  DisableKeyboard,
  EnableKeyboard,
  SetMask,
  ClearErrors,
  Setup,
  LimitSwitch
};

struct InstructionResult {
  InstructionKind kind = InstructionKind::Invalid;
  std::uint8_t error = 0; // 00h: valid (and applied, except Clear Errors: the device acts)
  std::size_t length = 1; // words this instruction spans (the rest of the BTW on 22h)
  int output = 0;         // LimitSwitch: the output (1..8) whose pairs were (re-)entered
};

struct InstructionRules {
  bool enforce_off_le_on = true; // R-ADV-2 (false on -04, or in the fault variant)
};

// The channel (0 or 1) whose position output `output` (1..8) follows (R-OA-1, R-OA-2).
[[nodiscard]] int owner_channel(const ModelTraits& model, const Setup& setup, int output);

// Validates the instruction that starts at words[0] and, when valid, applies it to setup
// with its side effects (SF -> CO := 0; 2742-18: SF -> CL := SF, SF or CL erases the
// channel's setpoints, R-SF-2).
[[nodiscard]] InstructionResult execute_instruction(std::span<const std::uint16_t> words,
                                                    const ModelTraits& model, const InstructionRules& rules,
                                                    Setup& setup);

} // namespace hilrig::models::pls2700
