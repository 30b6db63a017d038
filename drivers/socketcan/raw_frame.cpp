#include "drivers/socketcan/raw_frame.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <ctime>

namespace hilrig::socketcan {

RxControl read_rx_control(const msghdr& msg) noexcept {
  RxControl c;
  // CMSG_FIRSTHDR/CMSG_NXTHDR take a non-const msghdr but only read it.
  auto& m = const_cast<msghdr&>(msg);
  for (cmsghdr* h = CMSG_FIRSTHDR(&m); h != nullptr; h = CMSG_NXTHDR(&m, h)) {
    if (h->cmsg_level != SOL_SOCKET) continue;
    if (h->cmsg_type == SO_TIMESTAMPING && h->cmsg_len >= CMSG_LEN(sizeof(timespec))) {
      // struct scm_timestamping: ts[0] is the software stamp, the one asked for.
      timespec ts{};
      std::memcpy(&ts, CMSG_DATA(h), sizeof(ts));
      c.timestamp = Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
    } else if (h->cmsg_type == SO_RXQ_OVFL && h->cmsg_len >= CMSG_LEN(sizeof(std::uint32_t))) {
      std::memcpy(&c.queue_drops, CMSG_DATA(h), sizeof(c.queue_drops));
      c.has_drops = true;
    }
  }
  return c;
}

std::size_t to_raw(const CanFrame& frame, canfd_frame& raw) noexcept {
  raw = canfd_frame{}; // padding and reserved bytes go out as zeros
  raw.can_id = frame.id | (frame.extended ? CAN_EFF_FLAG : 0U) | (frame.rtr ? CAN_RTR_FLAG : 0U);
  raw.len = frame.len;
  if (frame.fd)
    raw.flags = static_cast<std::uint8_t>((frame.brs ? CANFD_BRS : 0) | (frame.esi ? CANFD_ESI : 0));
  std::memcpy(raw.data, frame.data.data(), std::min<std::size_t>(frame.len, sizeof(raw.data)));
  return frame.fd ? CANFD_MTU : CAN_MTU;
}

CanReceived from_raw(const canfd_frame& raw, std::size_t bytes, Nanos timestamp) noexcept {
  CanReceived r;
  r.timestamp = timestamp;
  if ((raw.can_id & CAN_ERR_FLAG) != 0) {
    r.is_error = true;
    std::array<std::uint8_t, 8> data{};
    std::memcpy(data.data(), raw.data, data.size());
    r.error = decode_error_frame(raw.can_id, data);
    return r;
  }
  CanFrame& f = r.frame;
  f.extended = (raw.can_id & CAN_EFF_FLAG) != 0;
  f.rtr = (raw.can_id & CAN_RTR_FLAG) != 0;
  f.id = raw.can_id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  f.fd = bytes == CANFD_MTU;
  f.brs = f.fd && (raw.flags & CANFD_BRS) != 0;
  f.esi = f.fd && (raw.flags & CANFD_ESI) != 0;
  f.len = raw.len;
  std::memcpy(f.data.data(), raw.data, std::min<std::size_t>(raw.len, f.data.size()));
  return r;
}

CanReceived read_received(const msghdr& msg, std::size_t bytes, std::uint32_t& queue_drops) noexcept {
  const RxControl c = read_rx_control(msg);
  if (c.has_drops) queue_drops = c.queue_drops;
  return from_raw(*static_cast<const canfd_frame*>(msg.msg_iov[0].iov_base), bytes, c.timestamp);
}

} // namespace hilrig::socketcan
