#include "drivers/socketcan/can_socket.hpp"

#include <linux/can.h>
#include <linux/can/raw.h>
#include <linux/net_tstamp.h>
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

// Made once per socket: a batch costs no allocation. Each header points at its own frame and
// control space for good; only the lengths are reset before a call.
struct CanSocket::Buffers {
  std::array<canfd_frame, kBatch> tx{};
  std::array<iovec, kBatch> tx_iov{};
  std::array<mmsghdr, kBatch> tx_msg{};
  std::array<canfd_frame, kBatch> rx{};
  std::array<iovec, kBatch> rx_iov{};
  std::array<mmsghdr, kBatch> rx_msg{};
  struct alignas(cmsghdr) Control {
    std::array<char, kRxControlBytes> bytes;
  };
  std::array<Control, kBatch> rx_control{};

  Buffers() {
    for (std::size_t k = 0; k < kBatch; ++k) {
      tx_iov[k] = iovec{&tx[k], sizeof(canfd_frame)};
      tx_msg[k].msg_hdr.msg_iov = &tx_iov[k];
      tx_msg[k].msg_hdr.msg_iovlen = 1;
      rx_iov[k] = iovec{&rx[k], sizeof(canfd_frame)};
      rx_msg[k].msg_hdr.msg_iov = &rx_iov[k];
      rx_msg[k].msg_hdr.msg_iovlen = 1;
      rx_msg[k].msg_hdr.msg_control = rx_control[k].bytes.data();
    }
  }
};

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
    : interface_(interface), fd_frames_(options.fd), io_(std::make_unique<Buffers>()) {
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
  // The software receive stamp, the same skb time SO_TIMESTAMP(NS) gives candump.
  const int stamping = SOF_TIMESTAMPING_RX_SOFTWARE | SOF_TIMESTAMPING_SOFTWARE;
  if (::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPING, &stamping, sizeof(stamping)) < 0)
    fail("SO_TIMESTAMPING");
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
  return send_batch(std::span<const CanFrame>(&frame, 1), deadline).status;
}

BatchSent CanSocket::send_batch(std::span<const CanFrame> frames, Nanos deadline) {
  // An FD frame on a classic socket cannot go: the frames before it still do.
  std::size_t sendable = frames.size();
  if (!fd_frames_) {
    sendable = static_cast<std::size_t>(
        std::find_if(frames.begin(), frames.end(), [](const CanFrame& f) { return f.fd; }) - frames.begin());
  }
  Buffers& io = *io_;
  auto send_many = [&](std::size_t first, std::size_t count) -> long {
    for (std::size_t k = 0; k < count; ++k) io.tx_iov[k].iov_len = to_raw(frames[first + k], io.tx[k]);
    const int n = ::sendmmsg(fd_, io.tx_msg.data(), static_cast<unsigned>(count), MSG_DONTWAIT);
    return n >= 0 ? n : -static_cast<long>(errno);
  };
  auto wait_for_room = [&] {
    const Nanos left = deadline - monotonic_now();
    if (left <= Nanos{0}) return false;
    pollfd p{fd_, POLLOUT, 0};
    ::poll(&p, 1, std::max(1, poll_ms(left)));
    return true;
  };
  BatchSent r = send_in_batches(sendable, kBatch, send_many, wait_for_room);
  if (r.status == SendStatus::Sent && sendable < frames.size()) {
    r.status = SendStatus::Failed;
    r.error = EINVAL;
  }
  if (r.error != 0) last_errno_ = r.error;
  return r;
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
  CanReceived r;
  if (receive_batch(std::span<CanReceived>(&r, 1), timeout) == 0) return std::nullopt;
  return r;
}

std::size_t CanSocket::receive_batch(std::span<CanReceived> out, Nanos timeout) {
  const auto want = static_cast<unsigned>(std::min(out.size(), kBatch));
  if (want == 0) return 0;
  Buffers& io = *io_;
  auto read_queued = [&] {
    for (unsigned k = 0; k < want; ++k) {
      io.rx_msg[k].msg_hdr.msg_controllen = kRxControlBytes;
      io.rx_msg[k].msg_hdr.msg_flags = 0;
    }
    return ::recvmmsg(fd_, io.rx_msg.data(), want, MSG_DONTWAIT, nullptr);
  };
  // Read first and wait only when nothing is queued: a busy bus costs one syscall a batch.
  int n = read_queued();
  if (n < 0 && errno == EAGAIN && timeout > Nanos{0}) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, poll_ms(timeout)) <= 0) return 0;
    n = read_queued();
  }
  if (n < 0) {
    last_errno_ = errno;
    return 0;
  }
  const auto got = static_cast<std::size_t>(n);
  for (std::size_t k = 0; k < got; ++k)
    out[k] = read_received(io.rx_msg[k].msg_hdr, io.rx_msg[k].msg_len, rx_queue_drops_);
  return got;
}

} // namespace hilrig::socketcan
