#pragma once
// A CAN or CAN FD frame as it travels on a bus (the fields SocketCAN's can_frame and
// canfd_frame carry), independent of any backend.

#include <array>
#include <cstdint>
#include <functional>

#include "core/time.hpp"

namespace hilrig {

struct CanFrame {
  std::uint32_t id = 0;  // 11-bit (standard) or 29-bit (extended) identifier
  bool extended = false; // IDE
  bool rtr = false;      // remote frame (classic CAN only)
  bool fd = false;       // CAN FD frame (FDF)
  bool brs = false;      // FD bit-rate switch in the data phase
  bool esi = false;      // FD error-state indicator
  std::uint8_t len = 0;  // payload bytes: 0..8 classic, 0..8,12,16,20,24,32,48,64 FD
  std::array<std::uint8_t, 64> data{};

  friend bool operator==(const CanFrame&, const CanFrame&) = default;
};

using CanReceiveHandler = std::function<void(const CanFrame& frame, Nanos timestamp)>;

// One node's attachment to a CAN bus.
class CanPort {
public:
  virtual ~CanPort() = default;
  // Queues a frame for transmission; the bus arbitrates and delivers it.
  virtual void send(const CanFrame& frame) = 0;
  // Called for each frame received from other nodes, stamped at its end of frame.
  virtual void on_receive(CanReceiveHandler handler) = 0;
};

} // namespace hilrig
