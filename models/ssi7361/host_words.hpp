#pragma once
// The 7361's backplane words (digest §5): the PLC writes %Q and %AQ1..6 (command words
// 0..6 here), and reads %I and %AI1..6 (status words 0..6). Register bit k of the manual
// is `1u << (k-1)`. 32-bit values take two words, low word first (§5.1).

#include <array>
#include <cstddef>
#include <cstdint>

namespace hilrig::models::ssi7361 {

inline constexpr std::size_t kCommandWords = 7; // %Q, %AQ1..%AQ6
inline constexpr std::size_t kStatusWords = 7;  // %I, %AI1..%AI6

using CommandWords = std::array<std::uint16_t, kCommandWords>;
using StatusWords = std::array<std::uint16_t, kStatusWords>;

// Command word indices.
namespace cmd {
inline constexpr std::size_t kQ = 0;          // %Q control bits
inline constexpr std::size_t kFormat = 1;     // %AQ1
inline constexpr std::size_t kMultiplier = 2; // %AQ2
inline constexpr std::size_t kDivisor = 3;    // %AQ3
inline constexpr std::size_t kPresetLow = 4;  // %AQ4
inline constexpr std::size_t kPresetHigh = 5; // %AQ5
inline constexpr std::size_t kRut = 6;        // %AQ6, ms
} // namespace cmd

// Status word indices.
namespace status {
inline constexpr std::size_t kI = 0;        // %I status bits
inline constexpr std::size_t kDataLow = 1;  // %AI1
inline constexpr std::size_t kDataHigh = 2; // %AI2
inline constexpr std::size_t kRateLow = 3;  // %AI3
inline constexpr std::size_t kRateHigh = 4; // %AI4
inline constexpr std::size_t kRawLow = 5;   // %AI5: stream bits 10..25
inline constexpr std::size_t kRawHigh = 6;  // %AI6: stream bits 1..9 in bits 09..01
} // namespace status

// %Q bits (L2080-2123).
namespace qbit {
inline constexpr std::uint16_t kApplyPreset = 0x0001;
inline constexpr std::uint16_t kFormat = 0x0002;
inline constexpr std::uint16_t kScalars = 0x0004;
inline constexpr std::uint16_t kPresetValue = 0x0008;
inline constexpr std::uint16_t kRut = 0x0010;
inline constexpr std::uint16_t kProgramDirection = 0x0020;
inline constexpr std::uint16_t kCountDirection = 0x0040; // 1 = Negative
inline constexpr std::uint16_t kCommands = 0x007F;       // bits 07-01
inline constexpr std::uint16_t kReserved = 0x3F80;       // bits 14-08: must be 0
inline constexpr std::uint16_t kE2Clear = 0x4000;
inline constexpr std::uint16_t kTransmit = 0x8000;
} // namespace qbit

// %I bits (L2011-2048).
namespace ibit {
inline constexpr std::uint16_t kFormatError = 0x0001;
inline constexpr std::uint16_t kScalarError = 0x0002;
inline constexpr std::uint16_t kPresetError = 0x0004;
inline constexpr std::uint16_t kRutError = 0x0008;
inline constexpr std::uint16_t kRateOverflow = 0x0020;
inline constexpr std::uint16_t kCommandError = 0x0040;
inline constexpr std::uint16_t kMessageIgnored = 0x0080;
inline constexpr std::uint16_t kEepromError = 0x1000;
inline constexpr std::uint16_t kAcknowledge = 0x8000;
// The errors that name a parameter, pending until that parameter is reprogrammed.
inline constexpr std::uint16_t kParameterErrors = kFormatError | kScalarError | kPresetError | kRutError;
} // namespace ibit

// %AQ1 Format word (L2126-2152).
namespace fbit {
inline constexpr std::uint16_t kBits = 0x001F;     // bits 05-01: N
inline constexpr std::uint16_t kGray = 0x0040;     // bit 07
inline constexpr std::uint16_t kNegative = 0x0080; // bit 08: Data Logic
inline constexpr std::uint16_t kMsb = 0x1F00;      // bits 13-09: M
inline constexpr std::uint16_t kClock500 = 0x8000; // bit 16
inline constexpr std::uint16_t kReserved = 0x6020; // bits 15-14 and 06: must be 0
} // namespace fbit

// Splits a signed 32-bit value into (low, high) words and joins them again.
[[nodiscard]] constexpr std::array<std::uint16_t, 2> split_words(std::int32_t value) {
  const auto u = static_cast<std::uint32_t>(value);
  return {static_cast<std::uint16_t>(u & 0xFFFFu), static_cast<std::uint16_t>(u >> 16)};
}
[[nodiscard]] constexpr std::int32_t join_words(std::uint16_t low, std::uint16_t high) {
  return static_cast<std::int32_t>((static_cast<std::uint32_t>(high) << 16) | low);
}

} // namespace hilrig::models::ssi7361
