#pragma once
// Builds Modbus TCP frames byte by byte from the MBAP layout (Modbus Messaging on TCP/IP
// Implementation Guide V1.0b, §3.1.3): transaction id 2, protocol id 2 (0 = Modbus),
// length 2 (unit id + PDU), unit id 1, then the PDU; tests state their expectations with it
// rather than with the server's own framing code.

#include <cstdint>
#include <vector>

namespace hilrig::test {

// `length` overrides the length field (a malformed frame); by default it counts unit + PDU.
inline std::vector<std::uint8_t> mbap_frame(std::uint16_t transaction, std::uint16_t protocol,
                                            std::uint8_t unit, const std::vector<std::uint8_t>& pdu,
                                            int length = -1) {
  const auto n = static_cast<std::uint16_t>(length < 0 ? pdu.size() + 1 : static_cast<std::size_t>(length));
  std::vector<std::uint8_t> f{static_cast<std::uint8_t>(transaction >> 8U),
                              static_cast<std::uint8_t>(transaction & 0xFFU),
                              static_cast<std::uint8_t>(protocol >> 8U),
                              static_cast<std::uint8_t>(protocol & 0xFFU),
                              static_cast<std::uint8_t>(n >> 8U),
                              static_cast<std::uint8_t>(n & 0xFFU),
                              unit};
  f.insert(f.end(), pdu.begin(), pdu.end());
  return f;
}

} // namespace hilrig::test
