#include "drivers/modbus/tcp_framing.hpp"

#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

namespace {
std::size_t be16(std::span<const std::uint8_t> p, std::size_t at) {
  return (std::size_t{p[at]} << 8U) | p[at + 1];
}
void put16(std::vector<std::uint8_t>& out, std::size_t v) {
  out.push_back(static_cast<std::uint8_t>((v >> 8U) & 0xFFU));
  out.push_back(static_cast<std::uint8_t>(v & 0xFFU));
}
} // namespace

TcpFrame next_tcp_frame(std::span<const std::uint8_t> stream) {
  if (stream.size() < 6) {
    return {};
  }
  const std::size_t length = be16(stream, 4); // unit id + PDU
  if (length < 2 || length > 1 + kMaxTcpPdu) {
    return {TcpFrameKind::Invalid, 0};
  }
  const std::size_t total = 6 + length;
  if (stream.size() < total) {
    return {};
  }
  const bool modbus = stream[2] == 0 && stream[3] == 0;
  return {modbus ? TcpFrameKind::Request : TcpFrameKind::Foreign, total};
}

RegisterStatus answer_tcp_request(RegisterMap& map, std::span<const std::uint8_t> frame,
                                  std::vector<std::uint8_t>& response, Fc23Read fc23_read) {
  if (frame.size() <= kMbapHeaderLength) {
    return RegisterStatus::IllegalDataValue; // not a request frame: nothing to answer
  }
  const std::span<const std::uint8_t> pdu = frame.subspan(kMbapHeaderLength);
  const PduResult result = handle_pdu(map, pdu, fc23_read);
  const bool ok = result.status == RegisterStatus::Ok;
  const std::size_t pdu_length = ok ? result.response.size() : 2;
  response.insert(response.end(), frame.begin(), frame.begin() + 2); // transaction id
  put16(response, 0);                                                // protocol id
  put16(response, pdu_length + 1);
  response.push_back(frame[6]); // unit id
  if (ok) {
    response.insert(response.end(), result.response.begin(), result.response.end());
  } else {
    response.push_back(static_cast<std::uint8_t>(pdu[0] | 0x80U));
    response.push_back(static_cast<std::uint8_t>(result.status));
  }
  return result.status;
}

} // namespace hilrig::drivers::modbus
