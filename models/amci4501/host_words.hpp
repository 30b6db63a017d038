#pragma once
// The 4501's SLC I/O image (digest §5): 8 output words (PLC -> module, O:s.0-7) and 8
// input words (module -> PLC, I:s.0-7), the bits of the control and status words, and the
// "div 1000 / mod 1000" split used for times and setpoints (L116, L170).

#include <array>
#include <cstddef>
#include <cstdint>

namespace hilrig::models::amci4501 {

inline constexpr std::size_t kWords = 8;
using InputWords = std::array<std::uint16_t, kWords>;  // I:s.0 .. I:s.7
using OutputWords = std::array<std::uint16_t, kWords>; // O:s.0 .. O:s.7

// Control word O:s.0 (L151-161).
namespace control {
inline constexpr std::uint16_t kReceived = 1u << 0;   // acknowledge the current result
inline constexpr std::uint16_t kClearError = 1u << 1; // clears No Response and Time Out
inline constexpr std::uint16_t kMode2 = 1u << 2;
inline constexpr std::uint16_t kMode3 = 1u << 3;
inline constexpr std::uint16_t kMode4 = 1u << 4;
inline constexpr std::uint16_t kMode5 = 1u << 5;
inline constexpr std::uint16_t kMode6 = 1u << 6;
inline constexpr std::uint16_t kModeBits = 0x007C;
inline constexpr std::uint16_t kReserved = 0x7F80; // bits 7-14
inline constexpr std::uint16_t kTransmit = 1u << 15;
} // namespace control

// Status word I:s.0 (L85-110).
namespace status {
inline constexpr std::uint16_t kNewValue = 1u << 0;
inline constexpr std::uint16_t kNoResponse = 1u << 1;
inline constexpr std::uint16_t kStartMark = 1u << 2;
inline constexpr std::uint16_t kLatchMark = 1u << 3;
inline constexpr std::uint16_t kCommandError = 1u << 4;
inline constexpr std::uint16_t kParameterError = 1u << 5;
inline constexpr std::uint16_t kTimeout = 1u << 6;
inline constexpr std::uint16_t kMode2 = 1u << 8; // modes 2..6 -> bits 8..12; mode 1: none
inline constexpr std::uint16_t kAcknowledge = 1u << 15;
} // namespace status

// Mode n's select bit in the control word and active bit in the status word (n = 2..6).
[[nodiscard]] constexpr std::uint16_t mode_select_bit(int mode) {
  return mode >= 2 && mode <= 6 ? static_cast<std::uint16_t>(1u << mode) : std::uint16_t{0};
}
[[nodiscard]] constexpr std::uint16_t mode_status_bit(int mode) {
  return mode >= 2 && mode <= 6 ? static_cast<std::uint16_t>(1u << (mode + 6)) : std::uint16_t{0};
}

// A value as upper = value div 1000, lower = value mod 1000 (L116, L170; A5, A6).
struct SplitWords {
  std::uint16_t upper = 0;
  std::uint16_t lower = 0;
  friend bool operator==(const SplitWords&, const SplitWords&) = default;
};
[[nodiscard]] constexpr SplitWords split_thousands(std::uint64_t value) {
  return {static_cast<std::uint16_t>(value / 1000), static_cast<std::uint16_t>(value % 1000)};
}
[[nodiscard]] constexpr std::uint64_t join_thousands(std::uint16_t upper, std::uint16_t lower) {
  return 1000u * static_cast<std::uint64_t>(upper) + lower;
}

} // namespace hilrig::models::amci4501
