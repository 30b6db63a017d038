#pragma once
// The bytes SocketCAN exchanges for one frame (canfd_frame, CAN_MTU or CANFD_MTU long) and
// what the kernel attaches to a received one (control messages): converted to and from
// CanFrame here, in one place, for the single-frame and the batched paths alike. Nothing
// here makes a syscall or allocates.

#include <linux/can.h>
#include <sys/socket.h>

#include <cstddef>
#include <cstdint>

#include "core/can_frame.hpp"
#include "core/time.hpp"
#include "drivers/socketcan/bus_state.hpp"

namespace hilrig::socketcan {

struct CanReceived {
  Nanos timestamp; // kernel receive time, CLOCK_REALTIME
  bool is_error = false;
  CanFrame frame;    // valid when !is_error
  ErrorReport error; // valid when is_error
};

// What the kernel says about one received frame beside its bytes.
struct RxControl {
  Nanos timestamp{0};            // SO_TIMESTAMPING software receive stamp (CLOCK_REALTIME); 0 if absent
  bool has_drops = false;        // an SO_RXQ_OVFL count came with the frame
  std::uint32_t queue_drops = 0; // the socket's drop counter when the frame was queued
};

// Room for the control messages a receive asks for: one scm_timestamping, one drop counter.
inline constexpr std::size_t kRxControlBytes =
    CMSG_SPACE(3 * sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t));

// The one reader of a received frame's control messages (SO_TIMESTAMPING, SO_RXQ_OVFL).
RxControl read_rx_control(const msghdr& msg) noexcept;

// Fills `raw` for sending `frame`; returns the bytes to send (CAN_MTU or CANFD_MTU).
std::size_t to_raw(const CanFrame& frame, canfd_frame& raw) noexcept;

// The frame or error frame in `raw`, `bytes` long as received, stamped `timestamp`.
CanReceived from_raw(const canfd_frame& raw, std::size_t bytes, Nanos timestamp) noexcept;

// One received message as recvmsg/recvmmsg left it: its canfd_frame in msg.msg_iov[0],
// `bytes` long, and its control messages. Updates `queue_drops` when a drop count came.
CanReceived read_received(const msghdr& msg, std::size_t bytes, std::uint32_t& queue_drops) noexcept;

} // namespace hilrig::socketcan
