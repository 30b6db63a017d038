#include "drivers/socketcan/can_socket.hpp"

#include <linux/can.h>
#include <linux/can/raw.h>
#include <linux/sock_diag.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <ctime>

namespace hilrig::socketcan {

namespace {

std::string why(const std::string& iface, const char* what, int err) {
  return "CAN " + iface + ": " + what + ": " + std::strerror(err);
}

Nanos monotonic_now() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

int poll_ms(Nanos remaining) {
  if (remaining <= Nanos{0}) return 0;
  return static_cast<int>(std::min<std::int64_t>((remaining.count() + 999'999) / 1'000'000, 60'000));
}

} // namespace

CanSocket::CanSocket(const std::string& interface, const CanSocketOptions& options)
    : interface_(interface), fd_frames_(options.fd) {
  fd_ = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd_ < 0) throw CanError(why(interface, "socket(PF_CAN)", errno));
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd_);
    throw CanError(why(interface, what, err));
  };
  ifreq ifr{};
  if (interface.size() >= IFNAMSIZ) {
    ::close(fd_);
    throw CanError("CAN " + interface + ": interface name too long");
  }
  std::memcpy(ifr.ifr_name, interface.c_str(), interface.size() + 1);
  if (::ioctl(fd_, SIOCGIFINDEX, &ifr) < 0) fail("no such interface");
  const int on = 1;
  if (options.fd && ::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &on, sizeof(on)) < 0) fail("CAN FD");
  if (options.receive_own && ::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &on, sizeof(on)) < 0) {
    fail("receive own");
  }
  if (!options.data_frames) {
    // An empty filter list: no data frame reaches the socket (error frames still do).
    if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FILTER, nullptr, 0) < 0) fail("filters");
  } else if (!options.filters.empty()) {
    std::vector<can_filter> f;
    for (const CanFilter& c : options.filters) {
      // The IDE bit is always in the mask: a standard filter never matches extended frames.
      f.push_back(can_filter{c.extended ? (c.id | CAN_EFF_FLAG) : c.id, c.mask | CAN_EFF_FLAG});
    }
    if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FILTER, f.data(),
                     static_cast<socklen_t>(f.size() * sizeof(can_filter))) < 0) {
      fail("filters");
    }
  }
  if (options.error_frames) {
    const can_err_mask_t mask = CAN_ERR_MASK;
    if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &mask, sizeof(mask)) < 0) fail("error filter");
  }
  if (::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on)) < 0) fail("SO_TIMESTAMPNS");
  if (::setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof(on)) < 0) fail("SO_RXQ_OVFL");
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) fail("bind");
}

CanSocket::~CanSocket() {
  if (fd_ >= 0) ::close(fd_);
}

SendStatus CanSocket::send(const CanFrame& frame, Nanos deadline) {
  canfd_frame raw{};
  raw.can_id = frame.id | (frame.extended ? CAN_EFF_FLAG : 0U) | (frame.rtr ? CAN_RTR_FLAG : 0U);
  raw.len = frame.len;
  if (frame.fd)
    raw.flags = static_cast<std::uint8_t>((frame.brs ? CANFD_BRS : 0) | (frame.esi ? CANFD_ESI : 0));
  std::memcpy(raw.data, frame.data.data(), std::min<std::size_t>(frame.len, sizeof(raw.data)));
  const std::size_t size = frame.fd ? CANFD_MTU : CAN_MTU;
  if (frame.fd && !fd_frames_) {
    last_errno_ = EINVAL;
    return SendStatus::Failed;
  }
  for (;;) {
    const ssize_t n = ::send(fd_, &raw, size, MSG_DONTWAIT);
    if (n == static_cast<ssize_t>(size)) return SendStatus::Sent;
    last_errno_ = errno;
    if (errno == ENETDOWN) return SendStatus::BusOff; // the controller took itself off the bus
    if (errno != EAGAIN && errno != ENOBUFS) return SendStatus::Failed;
    // Transmit queue full: wait for room, but never past the deadline.
    const Nanos left = deadline - monotonic_now();
    if (left <= Nanos{0}) return SendStatus::DeadlineMissed;
    pollfd p{fd_, POLLOUT, 0};
    ::poll(&p, 1, std::max(1, poll_ms(left)));
  }
}

std::uint32_t CanSocket::rx_queue_drops() const {
  std::array<std::uint32_t, SK_MEMINFO_VARS> meminfo{};
  socklen_t size = sizeof(meminfo);
  if (::getsockopt(fd_, SOL_SOCKET, SO_MEMINFO, meminfo.data(), &size) == 0 &&
      size > SK_MEMINFO_DROPS * sizeof(std::uint32_t))
    return std::max(rx_queue_drops_, meminfo[SK_MEMINFO_DROPS]);
  return rx_queue_drops_;
}

std::optional<CanReceived> CanSocket::receive(Nanos timeout) {
  canfd_frame raw{};
  iovec iov{&raw, sizeof(raw)};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t))];
  msghdr msg{};
  msg.msg_iov = &iov;
  msg.msg_iovlen = 1;
  msg.msg_control = control;
  msg.msg_controllen = sizeof(control);
  // Read first and wait only when nothing is queued: a busy bus costs one syscall a frame.
  ssize_t n = ::recvmsg(fd_, &msg, MSG_DONTWAIT);
  if (n < 0 && errno == EAGAIN && timeout > Nanos{0}) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, poll_ms(timeout)) <= 0) return std::nullopt;
    msg.msg_controllen = sizeof(control);
    n = ::recvmsg(fd_, &msg, MSG_DONTWAIT);
  }
  if (n < 0) {
    last_errno_ = errno;
    return std::nullopt;
  }
  CanReceived r;
  for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_TIMESTAMPNS) {
      timespec ts{};
      std::memcpy(&ts, CMSG_DATA(c), sizeof(ts));
      r.timestamp = Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
    } else if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
      std::memcpy(&rx_queue_drops_, CMSG_DATA(c), sizeof(rx_queue_drops_));
    }
  }
  if ((raw.can_id & CAN_ERR_FLAG) != 0) {
    r.is_error = true;
    std::array<std::uint8_t, 8> data{};
    std::memcpy(data.data(), raw.data, 8);
    r.error = decode_error_frame(raw.can_id, data);
    return r;
  }
  CanFrame& f = r.frame;
  f.extended = (raw.can_id & CAN_EFF_FLAG) != 0;
  f.rtr = (raw.can_id & CAN_RTR_FLAG) != 0;
  f.id = raw.can_id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  f.fd = n == static_cast<ssize_t>(CANFD_MTU);
  f.brs = f.fd && (raw.flags & CANFD_BRS) != 0;
  f.esi = f.fd && (raw.flags & CANFD_ESI) != 0;
  f.len = raw.len;
  std::memcpy(f.data.data(), raw.data, std::min<std::size_t>(raw.len, f.data.size()));
  return r;
}

} // namespace hilrig::socketcan
