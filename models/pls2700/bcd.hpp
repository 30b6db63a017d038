#pragma once
// BTW data words are BCD (L1368, L1392); BTR words are binary (L1316).
#include <cstdint>
#include <optional>

namespace hilrig::models::pls2700 {

// The value of a 4-digit BCD word, or nothing when a nibble is A..F.
[[nodiscard]] constexpr std::optional<int> from_bcd(std::uint16_t word) {
  int value = 0;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const int digit = (word >> shift) & 0xF;
    if (digit > 9) {
      return std::nullopt;
    }
    value = value * 10 + digit;
  }
  return value;
}

// 0..9999 as a BCD word (for hosts and tests).
[[nodiscard]] constexpr std::uint16_t to_bcd(int value) {
  unsigned word = 0;
  for (int shift = 0; shift < 16; shift += 4) {
    word |= static_cast<unsigned>(value % 10) << static_cast<unsigned>(shift);
    value /= 10;
  }
  return static_cast<std::uint16_t>(word);
}

} // namespace hilrig::models::pls2700
