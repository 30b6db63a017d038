#include "drivers/modbus/rtu_server.hpp"

#include <modbus/modbus.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <span>
#include <stdexcept>

namespace hilrig::drivers::modbus {
namespace {

// Waits up to `timeout` (to the nanosecond: 3.5 characters are under 2 ms) for `events`.
bool wait_for(int fd, short events, Nanos timeout) {
  pollfd pfd{fd, events, 0};
  const timespec ts{static_cast<time_t>(timeout.count() / 1'000'000'000),
                    static_cast<long>(timeout.count() % 1'000'000'000)};
  return ::ppoll(&pfd, 1, &ts, nullptr) > 0 && (pfd.revents & events) != 0;
}

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
    : map_(map), options_(std::move(options)), ctx_(new_context(options_)),
      silence_(rtu_silence(options_.format)) {
  if (modbus_connect(ctx_) != 0) {
    const std::string why = modbus_strerror(errno);
    modbus_free(ctx_);
    throw std::runtime_error("modbus rtu: cannot open " + options_.device + ": " + why);
  }
  owns_device_ = true;
  fd_ = modbus_get_socket(ctx_);
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
    : map_(map), options_(std::move(options)), ctx_(new_context(options_)), fd_(fd),
      silence_(rtu_silence(options_.format)) {
  if (options_.rs485) {
    rs485_note_ = "RS-485 mode not supported by a pty";
  }
}

RtuServer::~RtuServer() {
  if (owns_device_) {
    modbus_close(ctx_);
  }
  modbus_free(ctx_);
}

void RtuServer::run(const std::atomic<bool>& stop) {
  while (!stop.load()) {
    serve_once();
  }
}

void RtuServer::serve_once() {
  const bool began = wait_readable(options_.poll_period) && read_more();
  if (tick_) {
    tick_();
  }
  if (!began) {
    return;
  }
  while (pending_ > 0) {
    RtuFrame frame = next_rtu_frame(std::span(in_.data(), pending_), false);
    if (frame.kind == RtuFrameKind::Incomplete) {
      // A frame ends at the silence; one whose function fixes its length may be given longer
      // (options_.byte_timeout: an adapter that delivers bytes in bursts, as the RT VM lane's
      // emulated UART does).
      const std::optional<std::size_t> expected = rtu_request_length(std::span(in_.data(), pending_));
      const Nanos wait =
          expected && *expected > pending_ ? std::max(options_.byte_timeout, silence_) : silence_;
      if (wait_readable(wait) && read_more()) {
        continue;
      }
      frame = next_rtu_frame(std::span(in_.data(), pending_), true); // the line fell silent
    }
    take(frame);
  }
}

bool RtuServer::wait_readable(Nanos timeout) const { return wait_for(fd_, POLLIN, timeout); }

bool RtuServer::read_more() {
  const ssize_t n = ::read(fd_, in_.data() + pending_, in_.size() - pending_);
  if (n <= 0) {
    return false;
  }
  pending_ += static_cast<std::size_t>(n);
  return true;
}

// Acts on the first frame of the buffer and drops its bytes.
void RtuServer::take(const RtuFrame& frame) {
  const std::span<const std::uint8_t> bytes(in_.data(), frame.length);
  if (frame.kind == RtuFrameKind::BadCrc) {
    ++stats_.crc_errors; // dropped: the master repeats after its timeout
  } else {
    if (tick_) {
      tick_();
    }
    out_.clear();
    const RtuAnswer a = answer_rtu_request(map_, options_.unit, bytes, out_, options_.fc23_read);
    if (!a.addressed) {
      ++stats_.other_unit;
    } else {
      ++stats_.requests;
      if (a.broadcast) {
        ++stats_.broadcasts;
      } else if (a.status != RegisterStatus::Ok) {
        ++stats_.exceptions;
      }
      send(out_);
    }
  }
  std::copy(in_.begin() + static_cast<std::ptrdiff_t>(frame.length),
            in_.begin() + static_cast<std::ptrdiff_t>(pending_), in_.begin());
  pending_ -= frame.length;
}

void RtuServer::send(std::span<const std::uint8_t> bytes) {
  while (!bytes.empty()) {
    const ssize_t w = ::write(fd_, bytes.data(), bytes.size());
    if (w < 0 && (errno == EAGAIN || errno == EINTR)) {
      (void)wait_for(fd_, POLLOUT, options_.poll_period);
      continue;
    }
    if (w <= 0) {
      return; // the line is gone; the master's timeout tells it
    }
    bytes = bytes.subspan(static_cast<std::size_t>(w));
  }
}

} // namespace hilrig::drivers::modbus
