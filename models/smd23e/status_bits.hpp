#pragma once
// Bit positions of the SMD23E's command and status words (spec §6.4–§6.6).

#include <cstdint>

namespace hilrig::models::smd23e {

// Output word 0 in Command Mode (MSW), Modbus holding register 1024.
namespace msw {
inline constexpr std::uint16_t kAbsolute = 1U << 0;
inline constexpr std::uint16_t kRelative = 1U << 1;
inline constexpr std::uint16_t kHold = 1U << 2;
inline constexpr std::uint16_t kResume = 1U << 3;
inline constexpr std::uint16_t kImmediateStop = 1U << 4;
inline constexpr std::uint16_t kHomeCw = 1U << 5;
inline constexpr std::uint16_t kHomeCcw = 1U << 6;
inline constexpr std::uint16_t kJogCw = 1U << 7;
inline constexpr std::uint16_t kJogCcw = 1U << 8;
inline constexpr std::uint16_t kPresetPosition = 1U << 9;
inline constexpr std::uint16_t kResetErrors = 1U << 10;
inline constexpr std::uint16_t kProgramMove = 1U << 11;
inline constexpr std::uint16_t kProgramSegment = 1U << 12;
inline constexpr std::uint16_t kRunAssembled = 1U << 13;
inline constexpr std::uint16_t kPresetEncoder = 1U << 14;
inline constexpr std::uint16_t kConfigMode = 1U << 15;
} // namespace msw

// Output word 1 in Command Mode (LSW), Modbus holding register 1025.
namespace lsw {
inline constexpr std::uint16_t kEncoderMove = 1U << 2;
inline constexpr std::uint16_t kBlendCcw = 1U << 4;
inline constexpr std::uint16_t kSaveAssembled = 1U << 5;
inline constexpr std::uint16_t kRegistration = 1U << 7;
inline constexpr std::uint16_t kIndexed = 1U << 8;
inline constexpr std::uint16_t kDwellType = 1U << 9;
inline constexpr std::uint16_t kClearDriverFault = 1U << 10;
inline constexpr std::uint16_t kHomeProximity = 1U << 11;
inline constexpr std::uint16_t kDriveEnable = 1U << 15;
inline constexpr std::uint16_t kReserved = 0x7000 | (1U << 6) | (1U << 3) | (1U << 1) | (1U << 0);
} // namespace lsw

// Input word 0 in Command Mode: Status Word 1.
namespace sw1 {
inline constexpr std::uint16_t kMovingCw = 1U << 0;
inline constexpr std::uint16_t kMovingCcw = 1U << 1;
inline constexpr std::uint16_t kHoldState = 1U << 2;
inline constexpr std::uint16_t kStopped = 1U << 3;
inline constexpr std::uint16_t kHomed = 1U << 4;
inline constexpr std::uint16_t kAccelerating = 1U << 5;
inline constexpr std::uint16_t kDecelerating = 1U << 6;
inline constexpr std::uint16_t kMoveComplete = 1U << 7;
inline constexpr std::uint16_t kProgramMode = 1U << 8;
inline constexpr std::uint16_t kTransmitSegment = 1U << 9;
inline constexpr std::uint16_t kPositionInvalid = 1U << 10;
inline constexpr std::uint16_t kInputError = 1U << 11;
inline constexpr std::uint16_t kCommandError = 1U << 12;
inline constexpr std::uint16_t kConfigError = 1U << 13;
inline constexpr std::uint16_t kControllerOk = 1U << 14;
inline constexpr std::uint16_t kConfigMode = 1U << 15;
} // namespace sw1

// Input word 1 in Command Mode: Status Word 2.
namespace sw2 {
inline constexpr std::uint16_t kInput1 = 1U << 0;
inline constexpr std::uint16_t kInput2 = 1U << 1;
inline constexpr std::uint16_t kInput3 = 1U << 2;
inline constexpr std::uint16_t kTempWarning = 1U << 4;
inline constexpr std::uint16_t kPlcState = 1U << 5;
inline constexpr std::uint16_t kNetworkLost = 1U << 6;
inline constexpr std::uint16_t kDriverFault = 1U << 7;
inline constexpr std::uint16_t kInvalidJogChange = 1U << 9;
inline constexpr std::uint16_t kLimitCondition = 1U << 10;
inline constexpr std::uint16_t kHeartbeat = 1U << 11;
inline constexpr std::uint16_t kOut1Figure = 1U << 13;
inline constexpr std::uint16_t kStall = 1U << 14;
inline constexpr std::uint16_t kDriverEnabled = 1U << 15;
} // namespace sw2

// Configuration Control Word (output word 0 in Configuration Mode).
namespace ccw {
inline constexpr std::uint16_t kEncoderEnable = 1U << 10;
inline constexpr std::uint16_t kHomeProximityEnable = 1U << 11;
inline constexpr std::uint16_t kStallEnable = 1U << 13;
inline constexpr std::uint16_t kAntiResonanceOff = 1U << 14;
inline constexpr std::uint16_t kReserved = (1U << 12) | (1U << 9);
} // namespace ccw

// Configuration Word (output word 1 in Configuration Mode).
namespace cfgw {
inline constexpr std::uint16_t kSaveConfig = 1U << 10;
inline constexpr std::uint16_t kReadPresent = 1U << 11;
inline constexpr std::uint16_t kDriverEnable = 1U << 15;
inline constexpr std::uint16_t kReserved = 0x7000 | 0x03F8;
} // namespace cfgw

// Input functions, 3 bits per input (spec §5).
enum class InputFunction : std::uint8_t {
  GeneralPurpose = 0,
  CwLimit = 1,
  CcwLimit = 2,
  StartIndexed = 3,
  StopJog = 4,
  EmergencyStop = 5,
  Home = 6,
  Invalid = 7,
};

} // namespace hilrig::models::smd23e
