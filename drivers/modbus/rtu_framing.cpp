#include "drivers/modbus/rtu_framing.hpp"

#include <boost/crc.hpp>

#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

std::uint16_t rtu_crc(std::span<const std::uint8_t> bytes) {
  boost::crc_optimal<16, 0x8005, 0xFFFF, 0, true, true> crc; // CRC-16/MODBUS
  crc.process_bytes(bytes.data(), bytes.size());
  return crc.checksum();
}

bool rtu_crc_ok(std::span<const std::uint8_t> frame) {
  if (frame.size() < 4) {
    return false;
  }
  const std::uint16_t crc = rtu_crc(frame.first(frame.size() - 2));
  return frame[frame.size() - 2] == (crc & 0xFFU) && frame[frame.size() - 1] == (crc >> 8U);
}

std::optional<std::size_t> rtu_request_length(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 2) {
    return std::nullopt;
  }
  switch (bytes[1]) {
  case 1:
  case 2:
  case 3:
  case 4:
  case 5:
  case 6:
    return 8; // unit, function, address, count or value, CRC
  case 15:
  case 16:
    if (bytes.size() < 7) return std::nullopt;
    return 9 + std::size_t{bytes[6]}; // ... count, byte count, data, CRC
  case 22:
    return 10; // unit, function, address, AND mask, OR mask, CRC
  case 23:
    if (bytes.size() < 11) return std::nullopt;
    return 13 + std::size_t{bytes[10]};
  default:
    return std::nullopt;
  }
}

Nanos rtu_silence(const SerialFormat& format) {
  if (format.baud > 19'200 || format.baud == 0) {
    return microseconds(1'750);
  }
  // 3.5 characters, rounded up to the next nanosecond.
  const std::int64_t bits_x2 = 7 * static_cast<std::int64_t>(format.bits_per_char());
  const std::int64_t denominator = 2 * static_cast<std::int64_t>(format.baud);
  return nanoseconds((bits_x2 * 1'000'000'000 + denominator - 1) / denominator);
}

RtuFrame next_rtu_frame(std::span<const std::uint8_t> bytes, bool silent) {
  if (bytes.empty()) {
    return {};
  }
  const std::optional<std::size_t> by_function = rtu_request_length(bytes);
  if (by_function && *by_function <= bytes.size() && rtu_crc_ok(bytes.first(*by_function))) {
    return {RtuFrameKind::Request, *by_function};
  }
  const std::size_t here = std::min(bytes.size(), kMaxRtuAdu);
  if (!silent && bytes.size() < kMaxRtuAdu) {
    return {};
  }
  if (rtu_crc_ok(bytes.first(here))) {
    return {RtuFrameKind::Request, here};
  }
  // Two frames sent with no silence between them: drop the first by its length, so the
  // second is still read.
  if (by_function && *by_function < here) {
    return {RtuFrameKind::BadCrc, *by_function};
  }
  return {RtuFrameKind::BadCrc, here};
}

RtuAnswer answer_rtu_request(RegisterMap& map, std::uint8_t unit, std::span<const std::uint8_t> frame,
                             std::vector<std::uint8_t>& response, Fc23Read fc23_read) {
  RtuAnswer a;
  if (frame.size() < 4) {
    return a; // not a frame (unit, function, CRC): nobody is addressed
  }
  a.broadcast = frame[0] == kBroadcastUnit;
  a.addressed = a.broadcast || frame[0] == unit;
  if (!a.addressed) {
    return a;
  }
  const std::span<const std::uint8_t> pdu = frame.subspan(1, frame.size() - 3);
  const PduResult result = handle_pdu(map, pdu, fc23_read);
  a.status = result.status;
  if (a.broadcast) {
    return a; // never answered, not even with an exception
  }
  const std::size_t start = response.size();
  response.push_back(unit);
  if (result.status == RegisterStatus::Ok) {
    response.insert(response.end(), result.response.begin(), result.response.end());
  } else {
    response.push_back(static_cast<std::uint8_t>(pdu[0] | 0x80U));
    response.push_back(static_cast<std::uint8_t>(result.status));
  }
  const std::uint16_t crc = rtu_crc(std::span(response).subspan(start));
  response.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
  response.push_back(static_cast<std::uint8_t>(crc >> 8U));
  return a;
}

} // namespace hilrig::drivers::modbus
