#pragma once
// Modbus TCP framing, free of sockets so a test or a fuzzer can drive it byte for byte
// (Modbus Messaging on TCP/IP Implementation Guide V1.0b, §3.1.3, the MBAP header):
//   transaction id (2) | protocol id (2, 0 = Modbus) | length (2: unit id + PDU) | unit id (1) | PDU
// A stream is cut into frames by the MBAP length alone, never by the function code, so a
// request whose PDU is short or unknown still ends where its header says and the next one
// parses cleanly.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/register_map.hpp"
#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

inline constexpr std::size_t kMbapHeaderLength = 7; // up to and including the unit id
inline constexpr std::size_t kMaxTcpPdu = 253;      // Modbus Application Protocol V1.1b3, §4.1
inline constexpr std::size_t kMaxTcpAdu = kMbapHeaderLength + kMaxTcpPdu; // 260

enum class TcpFrameKind : std::uint8_t {
  Incomplete, // not a whole frame yet: read more
  Request,    // a Modbus request of `length` bytes: answer it
  Foreign,    // protocol id not 0: not Modbus, discarded unanswered (the guide's MBAP check)
  Invalid,    // a length field no Modbus frame can have (< 2 or > 254): the stream cannot be resynced
};

struct TcpFrame {
  TcpFrameKind kind = TcpFrameKind::Incomplete;
  std::size_t length = 0; // bytes of the stream the frame takes (Request, Foreign)
};

// Looks at the start of a received byte stream and says what its first frame is.
[[nodiscard]] TcpFrame next_tcp_frame(std::span<const std::uint8_t> stream);

// Answers one whole request frame (next_tcp_frame said Request) from the map: the response
// ADU, with the request's transaction and unit ids, is appended to `response`. A PDU the
// handler cannot parse (a truncated request whose MBAP length is consistent) is answered
// with exception 03, an unknown function with exception 01. Returns the status sent.
// Bytes too short to hold a function code are not a frame: nothing is appended.
// fc23_read: the served device's FC 23 (pdu_handler.hpp).
RegisterStatus answer_tcp_request(RegisterMap& map, std::span<const std::uint8_t> frame,
                                  std::vector<std::uint8_t>& response,
                                  Fc23Read fc23_read = Fc23Read::AfterWrite);

} // namespace hilrig::drivers::modbus
