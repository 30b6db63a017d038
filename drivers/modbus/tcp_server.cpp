#include "drivers/modbus/tcp_server.hpp"

#include <algorithm>
#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <span>
#include <stdexcept>

#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

namespace {
constexpr int kMbapLength = 7; // transaction id, protocol id, length, unit id

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + ": " + std::strerror(errno));
}

bool send_all(int fd, const std::uint8_t* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::send(fd, data, n, MSG_NOSIGNAL);
    if (w <= 0) {
      if (w < 0 && errno == EINTR) {
        continue;
      }
      return false;
    }
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}
} // namespace

TcpServer::TcpServer(RegisterMap& map, TcpServerOptions options) : map_(map), options_(std::move(options)) {
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(options_.port);
  if (::inet_pton(AF_INET, options_.bind.c_str(), &addr.sin_addr) != 1) {
    throw std::runtime_error("modbus tcp: not an IPv4 address: " + options_.bind);
  }
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) {
    fail("modbus tcp: socket");
  }
  const int yes = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  if (::bind(listen_fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0 ||
      ::listen(listen_fd_, options_.max_connections) != 0) {
    const int err = errno;
    ::close(listen_fd_);
    errno = err;
    fail("modbus tcp: cannot listen on " + options_.bind + ":" + std::to_string(options_.port));
  }
  socklen_t len = sizeof addr;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
  // The context only frames requests and builds exception replies; we own the sockets.
  ctx_ = modbus_new_tcp(options_.bind.c_str(), port_);
  if (ctx_ == nullptr) {
    ::close(listen_fd_);
    fail("modbus tcp: modbus_new_tcp");
  }
  modbus_set_indication_timeout(ctx_, 1, 0); // a half-sent request cannot stall the server
}

TcpServer::~TcpServer() {
  for (int fd : clients_) {
    ::close(fd);
  }
  if (listen_fd_ >= 0) {
    ::close(listen_fd_);
  }
  if (ctx_ != nullptr) {
    modbus_set_socket(ctx_, -1);
    modbus_free(ctx_);
  }
}

void TcpServer::run(const std::atomic<bool>& stop) {
  while (!stop.load()) {
    serve_once();
  }
}

void TcpServer::serve_once() {
  std::array<pollfd, 17> fds{};
  std::size_t n = 0;
  fds[n++] = {listen_fd_, POLLIN, 0};
  for (int fd : clients_) {
    if (n < fds.size()) {
      fds[n++] = {fd, POLLIN, 0};
    }
  }
  const int timeout_ms =
      static_cast<int>(std::max<std::int64_t>(1, options_.poll_period.count() / 1'000'000));
  const int ready = ::poll(fds.data(), n, timeout_ms);
  if (tick_) {
    tick_();
  }
  if (ready <= 0) {
    return;
  }
  for (std::size_t i = n; i-- > 1;) {
    if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) != 0 && !answer(fds[i].fd)) {
      close_client(i - 1);
    }
  }
  if ((fds[0].revents & POLLIN) != 0) {
    accept_client();
  }
}

void TcpServer::accept_client() {
  const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
  if (fd < 0) {
    return;
  }
  if (static_cast<int>(clients_.size()) >= options_.max_connections) {
    ::close(fd);
    return;
  }
  clients_.push_back(fd);
  ++stats_.connections;
}

void TcpServer::close_client(std::size_t index) {
  ::close(clients_[index]);
  clients_.erase(clients_.begin() + static_cast<std::ptrdiff_t>(index));
}

bool TcpServer::answer(int fd) {
  std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> req{};
  modbus_set_socket(ctx_, fd);
  const int rc = modbus_receive(ctx_, req.data());
  if (rc <= 0) {
    return rc == 0; // -1: closed, timed out or garbled beyond framing
  }
  ++stats_.requests;
  const auto len = static_cast<std::size_t>(rc);
  // libmodbus frames by function code; bytes the MBAP length announces beyond that
  // (an unknown function's data) are drained so the next request parses cleanly.
  const std::size_t announced = 6U + ((std::size_t{req[4]} << 8U) | req[5]);
  bool length_mismatch = announced != len;
  for (std::size_t extra = announced > len ? announced - len : 0; extra > 0;) {
    std::array<std::uint8_t, 256> sink{};
    const ssize_t r = ::recv(fd, sink.data(), std::min(extra, sink.size()), MSG_DONTWAIT);
    if (r <= 0) {
      break;
    }
    extra -= static_cast<std::size_t>(r);
  }
  if (tick_) {
    tick_();
  }
  const std::span<const std::uint8_t> pdu(req.data() + kMbapLength, len - kMbapLength);
  PduResult result = handle_pdu(map_, pdu);
  if (length_mismatch && result.status == RegisterStatus::Ok && pdu[0] != 0) {
    // A request whose length field disagrees with its function's format is malformed.
    result.status = RegisterStatus::IllegalDataValue;
  }
  if (result.status != RegisterStatus::Ok) {
    ++stats_.exceptions;
    return modbus_reply_exception(ctx_, req.data(), static_cast<unsigned>(result.status)) > 0;
  }
  std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> adu{};
  const std::size_t pdu_len = result.response.size();
  adu[0] = req[0]; // transaction id echoes the request
  adu[1] = req[1];
  adu[2] = 0; // protocol id
  adu[3] = 0;
  adu[4] = static_cast<std::uint8_t>((pdu_len + 1U) >> 8U);
  adu[5] = static_cast<std::uint8_t>((pdu_len + 1U) & 0xFFU);
  adu[6] = req[6]; // unit id
  std::memcpy(adu.data() + kMbapLength, result.response.data(), pdu_len);
  return send_all(fd, adu.data(), kMbapLength + pdu_len);
}

} // namespace hilrig::drivers::modbus
