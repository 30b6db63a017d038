#include "drivers/modbus/rtu_server.hpp"

#include <modbus/modbus.h>
#include <poll.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <span>
#include <stdexcept>

#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

namespace {

constexpr std::size_t kCrcLength = 2;
// How long a foreign unit's reply may take to follow its request before the line is
// taken as idle again [MODEL: Modbus leaves the response timeout to the master].
constexpr int kForeignReplyWindowUs = 50'000;

char parity_letter(Parity p) { return p == Parity::Even ? 'E' : p == Parity::Odd ? 'O' : 'N'; }

modbus_t* new_context(const RtuServerOptions& o) {
  if (o.unit < 1 || o.unit > 247) {
    throw std::invalid_argument("modbus rtu: unit id must be 1..247, not " + std::to_string(o.unit));
  }
  const std::string device = o.device.empty() ? std::string("fd") : o.device;
  modbus_t* ctx = modbus_new_rtu(device.c_str(), static_cast<int>(o.format.baud),
                                 parity_letter(o.format.parity), o.format.data_bits, o.format.stop_bits);
  if (ctx == nullptr) {
    throw std::runtime_error("modbus rtu: " + device + ": " + modbus_strerror(errno));
  }
  modbus_set_slave(ctx, o.unit);
  return ctx;
}

} // namespace

RtuServer::RtuServer(RegisterMap& map, RtuServerOptions options)
    : map_(map), options_(std::move(options)), ctx_(new_context(options_)) {
  if (modbus_connect(ctx_) != 0) {
    const std::string why = modbus_strerror(errno);
    modbus_free(ctx_);
    throw std::runtime_error("modbus rtu: cannot open " + options_.device + ": " + why);
  }
  owns_device_ = true;
  if (options_.rs485) {
    if (modbus_rtu_set_serial_mode(ctx_, MODBUS_RTU_RS485) == 0) {
      rs485_active_ = true;
    } else {
      rs485_note_ =
          std::string("RS-485 mode not supported by ") + options_.device + ": " + modbus_strerror(errno);
    }
  }
}

RtuServer::RtuServer(RegisterMap& map, int fd, RtuServerOptions options)
    : map_(map), options_(std::move(options)), ctx_(new_context(options_)) {
  modbus_set_socket(ctx_, fd);
  if (options_.rs485) {
    rs485_note_ = "RS-485 mode not supported by a pty";
  }
}

RtuServer::~RtuServer() {
  if (owns_device_) {
    modbus_close(ctx_);
  } else {
    modbus_set_socket(ctx_, -1); // the fd belongs to the caller
  }
  modbus_free(ctx_);
}

void RtuServer::run(const std::atomic<bool>& stop) {
  while (!stop.load()) {
    serve_once();
  }
}

void RtuServer::serve_once() {
  pollfd pfd{modbus_get_socket(ctx_), POLLIN, 0};
  const int timeout_ms =
      static_cast<int>(std::max<std::int64_t>(1, options_.poll_period.count() / 1'000'000));
  const int ready = ::poll(&pfd, 1, timeout_ms);
  if (tick_) {
    tick_();
  }
  if (ready > 0 && (pfd.revents & POLLIN) != 0) {
    answer();
  }
}

void RtuServer::answer() {
  std::array<std::uint8_t, MODBUS_RTU_MAX_ADU_LENGTH> req{};
  const int rc = modbus_receive(ctx_, req.data());
  if (rc < 0) {
    if (errno == EMBBADCRC) {
      ++stats_.crc_errors; // dropped: the master repeats after its timeout
    }
    return; // a frame cut short (byte timeout) is dropped the same way
  }
  if (rc == 0) {
    skip_foreign_reply();
    ++stats_.other_unit; // counted once the line is idle again
    return;
  }
  ++stats_.requests;
  const std::uint8_t unit = req[0];
  const bool broadcast = unit == MODBUS_BROADCAST_ADDRESS;
  if (broadcast) {
    ++stats_.broadcasts;
  }
  if (tick_) {
    tick_();
  }
  const auto len = static_cast<std::size_t>(rc);
  const std::span<const std::uint8_t> pdu(req.data() + 1, len - 1 - kCrcLength);
  const PduResult result = handle_pdu(map_, pdu);
  if (broadcast) {
    return; // broadcasts are never answered, not even with an exception
  }
  std::array<std::uint8_t, MODBUS_RTU_MAX_ADU_LENGTH> rsp{};
  std::size_t n = 0;
  rsp[n++] = unit;
  if (result.status != RegisterStatus::Ok) {
    ++stats_.exceptions;
    rsp[n++] = static_cast<std::uint8_t>(pdu[0] | 0x80U);
    rsp[n++] = static_cast<std::uint8_t>(result.status);
  } else {
    std::memcpy(rsp.data() + n, result.response.data(), result.response.size());
    n += result.response.size();
  }
  // libmodbus appends the CRC.
  modbus_send_raw_request(ctx_, rsp.data(), static_cast<int>(n));
}

// libmodbus expects the addressed unit's reply to follow a foreign request and reads it as
// a confirmation to skip. Do that now, within a bounded window, so that a silent foreign
// unit cannot make the server swallow the next request meant for it.
void RtuServer::skip_foreign_reply() {
  std::array<std::uint8_t, MODBUS_RTU_MAX_ADU_LENGTH> sink{};
  std::uint32_t sec = 0;
  std::uint32_t usec = 0;
  modbus_get_response_timeout(ctx_, &sec, &usec);
  modbus_set_response_timeout(ctx_, 0, kForeignReplyWindowUs);
  modbus_receive(ctx_, sink.data());
  modbus_set_response_timeout(ctx_, sec, usec);
}

} // namespace hilrig::drivers::modbus
