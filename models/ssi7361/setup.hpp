#pragma once
// The 7361's programmable parameters (digest §3) with their factory defaults (L2154-2166),
// and the %AQ1 Format word they are programmed from.

#include <cstdint>

#include "models/ssi7361/host_words.hpp"

namespace hilrig::models::ssi7361 {

// The SSI Setup: what the Format command programs (%AQ1).
struct SsiSetup {
  bool clock_500khz = false; // 125 kHz default
  unsigned msb = 1;          // M: stream bit of the field's MSB
  unsigned bits = 24;        // N: field width
  bool gray = false;         // Data Type
  bool negative_logic = false;
  friend bool operator==(const SsiSetup&, const SsiSetup&) = default;
};

struct Setup {
  SsiSetup ssi{};
  bool count_negative = false;
  std::uint16_t multiplier = 1;
  std::uint16_t divisor = 1;
  std::int32_t preset = 0;
  std::uint16_t rut_ms = 100;
  friend bool operator==(const Setup&, const Setup&) = default;
};

// The Format word's fields, read without any check (M and N are 5-bit fields).
[[nodiscard]] constexpr SsiSetup decode_format(std::uint16_t word) {
  SsiSetup s;
  s.clock_500khz = (word & fbit::kClock500) != 0;
  s.msb = static_cast<unsigned>((word & fbit::kMsb) >> 8);
  s.bits = static_cast<unsigned>(word & fbit::kBits);
  s.gray = (word & fbit::kGray) != 0;
  s.negative_logic = (word & fbit::kNegative) != 0;
  return s;
}

// The Format command's ranges (L2126-2133 N, L2143-2148 M, L2162-2163): a cycle that
// programs anything outside them sets FMTErr and keeps the old setup. The one copy of the
// rule: the programming cycle and `hilrig synth ssi` both judge by format_fault().
inline constexpr unsigned kMinDataBits = 2;     // N
inline constexpr unsigned kMaxDataBits = 25;    // N
inline constexpr unsigned kMinMsb = 1;          // M
inline constexpr unsigned kMaxMsb = 24;         // M
inline constexpr unsigned kMaxMsbPlusBits = 26; // M + N: the field ends by stream bit 25

// Which part of a Format is out of range, in the manual's order (N, then M, then M + N).
enum class FormatFault : std::uint8_t { None, DataBits, Msb, MsbPlusBits };

[[nodiscard]] constexpr FormatFault format_fault(const SsiSetup& s) {
  if (s.bits < kMinDataBits || s.bits > kMaxDataBits) return FormatFault::DataBits;
  if (s.msb < kMinMsb || s.msb > kMaxMsb) return FormatFault::Msb;
  if (s.msb + s.bits > kMaxMsbPlusBits) return FormatFault::MsbPlusBits;
  return FormatFault::None;
}
[[nodiscard]] constexpr bool format_valid(const SsiSetup& s) { return format_fault(s) == FormatFault::None; }

[[nodiscard]] constexpr std::uint16_t encode_format(const SsiSetup& s) {
  return static_cast<std::uint16_t>((s.clock_500khz ? fbit::kClock500 : 0u) | ((s.msb & 0x1Fu) << 8) |
                                    (s.negative_logic ? fbit::kNegative : 0u) | (s.gray ? fbit::kGray : 0u) |
                                    (s.bits & 0x1Fu));
}

} // namespace hilrig::models::ssi7361
