#pragma once
// The SMD23E's 1000-based multi-word format (spec §6.3): a 32-bit-range value travels as two
// signed 16-bit words, value = upper × 1000 + lower, |lower| ≤ 999, both words carrying the
// value's sign. Example: −7,654,321 = (−7654, −321) = (0xE21A, 0xFEBF).

#include <cstdint>
#include <optional>

namespace hilrig::models::smd23e {

struct MultiWord {
  std::uint16_t upper = 0;
  std::uint16_t lower = 0;
  friend bool operator==(const MultiWord&, const MultiWord&) = default;
};

[[nodiscard]] constexpr std::int16_t as_signed(std::uint16_t w) { return static_cast<std::int16_t>(w); }
[[nodiscard]] constexpr std::uint16_t as_word(std::int32_t v) {
  return static_cast<std::uint16_t>(v & 0xFFFF);
}

// Splits a value; C++ division truncates toward zero, so both words carry the sign.
// Values outside −32,768,000 … 32,767,999 do not fit and are clamped to those extremes.
[[nodiscard]] constexpr MultiWord encode_multiword(std::int64_t value) {
  constexpr std::int64_t lo = -32'768'000;
  constexpr std::int64_t hi = 32'767'999;
  const std::int64_t v = value < lo ? lo : (value > hi ? hi : value);
  return {as_word(static_cast<std::int32_t>(v / 1000)), as_word(static_cast<std::int32_t>(v % 1000))};
}

// Joins two words; nullopt when the lower word is out of ±999 or the signs disagree.
[[nodiscard]] constexpr std::optional<std::int32_t> decode_multiword(std::uint16_t upper,
                                                                     std::uint16_t lower) {
  const std::int32_t u = as_signed(upper);
  const std::int32_t l = as_signed(lower);
  if (l > 999 || l < -999) {
    return std::nullopt;
  }
  if ((u > 0 && l < 0) || (u < 0 && l > 0)) {
    return std::nullopt;
  }
  return u * 1000 + l;
}

} // namespace hilrig::models::smd23e
