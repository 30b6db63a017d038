#pragma once
// The programming error byte (status word bits 8..15), pls2700.md §5.5: all 21 codes.
// The "n" codes carry the output number (8n, Cn, Dn, En, Fn) or the pair count (An) in
// their low digit.
#include <cstdint>

namespace hilrig::models::pls2700::error {

inline constexpr std::uint8_t kNone = 0x00;
inline constexpr std::uint8_t kInvalidCommand = 0x21;
inline constexpr std::uint8_t kInvalidLength = 0x22;
inline constexpr std::uint8_t kMessageIgnored = 0x24;
inline constexpr std::uint8_t kInvalidSf1 = 0x41;
inline constexpr std::uint8_t kInvalidCo1 = 0x42;
inline constexpr std::uint8_t kInvalidCl1 = 0x43;
inline constexpr std::uint8_t kInvalidTr1 = 0x44;
inline constexpr std::uint8_t kInvalidIpOt1 = 0x45;
inline constexpr std::uint8_t kInvalidOa = 0x48;
inline constexpr std::uint8_t kInvalidSf2 = 0x51;
inline constexpr std::uint8_t kInvalidCo2 = 0x52;
inline constexpr std::uint8_t kInvalidCl2 = 0x53;
inline constexpr std::uint8_t kInvalidTr2 = 0x54;
inline constexpr std::uint8_t kInvalidIpOt2 = 0x55;
// Channel-1 code + 0x10 = the channel-2 code.
inline constexpr std::uint8_t kChannel2 = 0x10;

[[nodiscard]] constexpr std::uint8_t invalid_ls(unsigned digit) {
  return static_cast<std::uint8_t>(0x80 | (digit & 0xF));
}
[[nodiscard]] constexpr std::uint8_t invalid_sp(unsigned digit) {
  return static_cast<std::uint8_t>(0xA0 | (digit & 0xF));
}
[[nodiscard]] constexpr std::uint8_t invalid_on(int output) {
  return static_cast<std::uint8_t>(0xC0 | output);
}
[[nodiscard]] constexpr std::uint8_t invalid_off(int output) {
  return static_cast<std::uint8_t>(0xD0 | output);
}
[[nodiscard]] constexpr std::uint8_t invalid_on_advance(int output) {
  return static_cast<std::uint8_t>(0xE0 | output);
}
[[nodiscard]] constexpr std::uint8_t invalid_off_advance(int output) {
  return static_cast<std::uint8_t>(0xF0 | output);
}

} // namespace hilrig::models::pls2700::error
