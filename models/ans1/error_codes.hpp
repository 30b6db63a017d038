#pragma once
// The ANS1's programming error codes (status word 0 bits 11..8; spec §5.6, manual L2304-L2309).
// Codes 1001..1100 stay until a block with Clear Errors (bit 4) arrives; 1000 is cleared by the
// next valid command word. A rejected block changes nothing [MODEL §5.6] but is still
// acknowledged [MODEL A43].
#include <cstdint>
#include <string_view>

namespace hilrig::models::ans1 {

enum class ErrorCode : std::uint8_t {
  None = 0b0000,              // L2304
  CommandWord = 0b1000,       // L2305: undefined block number (12..14) [MODEL A43]
  Parameter = 0b1001,         // L2306: a value is out of its range
  ReservedBits = 0b1010,      // L2307: a reserved bit is 1
  ParameterConflict = 0b1011, // L2308: incompatible parameters or Apply bits; "cannot be accepted"
  SetpointOverlap = 0b1100,   // L2309, L1907: pairs on one output overlap
};

[[nodiscard]] constexpr std::string_view error_name(ErrorCode code) {
  switch (code) {
  case ErrorCode::None:
    return "No Error";
  case ErrorCode::CommandWord:
    return "Command Word Error";
  case ErrorCode::Parameter:
    return "Parameter Error";
  case ErrorCode::ReservedBits:
    return "Reserved Bits Error";
  case ErrorCode::ParameterConflict:
    return "Parameter Conflict";
  case ErrorCode::SetpointOverlap:
    return "Setpoint Overlap Error";
  }
  return "unknown";
}

// The code's place in status word 0 (bits 11..8).
[[nodiscard]] constexpr std::uint16_t error_bits(ErrorCode code) {
  return static_cast<std::uint16_t>(static_cast<unsigned>(code) << 8);
}

[[nodiscard]] constexpr ErrorCode error_from_status(std::uint16_t status_word0) {
  return static_cast<ErrorCode>((status_word0 >> 8) & 0x0FU);
}

} // namespace hilrig::models::ans1
