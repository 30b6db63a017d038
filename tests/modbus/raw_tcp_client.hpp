#pragma once
// A raw loopback TCP client for the Modbus TCP server tests: sends bytes as given (any
// MBAP, well-formed or not) and reads exactly what comes back. Every wait is bounded (a
// failure bound, never a measurement).

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "drivers/modbus/tcp_server.hpp"
#include "tests/modbus/mbap_bytes.hpp"

namespace hilrig::test {

class RawTcpClient {
public:
  // The receive buffer stays as the kernel sizes it. Shrunk to 4 KiB (so that a client that
  // reads nothing fills up sooner), one flooder in ten on a busy machine stalled for minutes
  // on Linux 6.18 loopback (ss: its receive queue past its buffer and dropping, the server's
  // receive queue empty, yet the client probing a zero window at back-off 7-9 and the
  // server retransmitting): no byte either way, so the server rightly timed it out.
  explicit RawTcpClient(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0)) {
    const timeval bound{.tv_sec = 10, .tv_usec = 0}; // a send blocked this long fails
    ::setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &bound, sizeof bound);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0;
  }
  RawTcpClient(const RawTcpClient&) = delete;
  RawTcpClient& operator=(const RawTcpClient&) = delete;
  ~RawTcpClient() { ::close(fd_); }

  [[nodiscard]] bool connected() const { return connected_; }
  // False when not all was sent: the server closed, or the bytes waited 10 s for room.
  bool send(const std::vector<std::uint8_t>& bytes) {
    return ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
  }
  // Reads exactly n bytes; fewer when the server closes or nothing comes for 10 s.
  std::vector<std::uint8_t> receive(std::size_t n) {
    std::vector<std::uint8_t> got;
    while (got.size() < n) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 10'000) <= 0) break;
      std::array<std::uint8_t, 512> buf{};
      const ssize_t r = ::recv(fd_, buf.data(), std::min(buf.size(), n - got.size()), 0);
      if (r <= 0) break;
      got.insert(got.end(), buf.begin(), buf.begin() + r);
    }
    return got;
  }
  // True when the server has closed this connection (EOF or reset within 10 s).
  bool closed_by_server() {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 10'000) <= 0) return false;
    std::array<std::uint8_t, 64> buf{};
    return ::recv(fd_, buf.data(), buf.size(), 0) <= 0;
  }

private:
  int fd_;
  bool connected_ = false;
};

// Blocks until the server has exactly n connections open (std::atomic::wait: no polling).
inline void wait_for_open(const drivers::modbus::TcpServerStats& s, std::size_t n) {
  for (std::size_t now = s.open.load(); now != n; now = s.open.load()) {
    s.open.wait(now);
  }
}

} // namespace hilrig::test
