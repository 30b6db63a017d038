#pragma once
// Modbus RTU framing, free of the serial line so a test or a fuzzer can drive it byte for byte
// (Modbus over Serial Line V1.02): unit id (1) | PDU | CRC-16 (2, low byte first, §6.2.2).
// A frame ends where a silence of 3.5 character times falls (§2.5.1.1). So as not to wait
// that long for every request, a request whose function code fixes its length is complete as
// soon as that many bytes have arrived with a good CRC; anything else (an unknown function,
// a short or overlong PDU) ends at the silence and is still answered when its CRC is good.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/register_map.hpp"
#include "core/serial.hpp"
#include "core/time.hpp"
#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

inline constexpr std::size_t kMaxRtuAdu = 256; // §2.5.1.1: unit + 253-byte PDU + CRC
inline constexpr std::uint8_t kBroadcastUnit = 0;

// CRC-16/MODBUS of `bytes` (polynomial 0xA001 reflected, initial 0xFFFF).
[[nodiscard]] std::uint16_t rtu_crc(std::span<const std::uint8_t> bytes);
// True when the last two bytes are the CRC of the ones before (and there are at least 4).
[[nodiscard]] bool rtu_crc_ok(std::span<const std::uint8_t> frame);

// The length a request frame has by its function code (and byte count), once enough of it
// has arrived to tell; nullopt when the function code does not fix it or too little is here.
[[nodiscard]] std::optional<std::size_t> rtu_request_length(std::span<const std::uint8_t> bytes);

// 3.5 character times at this serial format: 11-bit characters at 8E1; 1.75 ms above 19,200
// baud (§2.5.1.1, the fixed value for high rates).
[[nodiscard]] Nanos rtu_silence(const SerialFormat& format);

enum class RtuFrameKind : std::uint8_t {
  Incomplete, // wait for more bytes or for the silence
  Request,    // a frame with a good CRC of `length` bytes
  BadCrc,     // `length` bytes to drop: their CRC is wrong
};

struct RtuFrame {
  RtuFrameKind kind = RtuFrameKind::Incomplete;
  std::size_t length = 0;
};

// Looks at the bytes received since the line was last idle and says what the first frame is.
// `silent`: the line has been quiet for 3.5 character times since the last byte, so whatever
// is here is all the frame there is. Bytes beyond kMaxRtuAdu end a frame too.
[[nodiscard]] RtuFrame next_rtu_frame(std::span<const std::uint8_t> bytes, bool silent);

struct RtuAnswer {
  bool addressed = false; // for this unit or broadcast (else ignored)
  bool broadcast = false; // carried out, never answered (§2.2)
  RegisterStatus status = RegisterStatus::Ok;
};

// Carries out one request frame (RtuFrameKind::Request) for unit `unit`: the reply ADU with
// its CRC is appended to `response` unless the frame was for another unit or a broadcast.
// Fewer than 4 bytes are not a frame: not addressed, nothing appended.
// fc23_read: the served device's FC 23 (pdu_handler.hpp).
RtuAnswer answer_rtu_request(RegisterMap& map, std::uint8_t unit, std::span<const std::uint8_t> frame,
                             std::vector<std::uint8_t>& response, Fc23Read fc23_read = Fc23Read::AfterWrite);

} // namespace hilrig::drivers::modbus
