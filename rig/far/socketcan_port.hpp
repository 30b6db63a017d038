#pragma once
// A SocketCAN interface as a core CanPort for a model on the far side (the resolver-emulator
// node). poll(t), with the model's clock behind or at t, takes every frame received since
// the last poll and hands it to the port's handlers at its kernel receive time moved onto the
// model's clock (t minus the frame's age; never before the scheduler's now): the model sees
// frames in time order, spread as they came, however late the poll. Controller error frames
// are counted. send() queues a frame without waiting.

#include <cstdint>
#include <string>
#include <vector>

#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "drivers/socketcan/bus_state.hpp"
#include "drivers/socketcan/can_socket.hpp"

namespace hilrig::far {

class SocketCanPort final : public CanPort {
public:
  // Throws socketcan::CanError when the interface cannot be opened.
  SocketCanPort(Scheduler& scheduler, const std::string& interface);

  void send(const CanFrame& frame) override;
  void on_receive(CanReceiveHandler handler) override { handlers_.push_back(std::move(handler)); }

  // Schedules what arrived for delivery; returns the number of data frames.
  std::size_t poll(Nanos t);

  [[nodiscard]] const std::string& interface() const { return socket_.interface(); }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t error_frames() const { return error_frames_; }
  [[nodiscard]] std::uint64_t send_failures() const { return send_failures_; }
  [[nodiscard]] socketcan::BusState state() const { return tracker_.state(); }

private:
  void deliver(const CanFrame& frame, Nanos at) const;

  Scheduler& scheduler_;
  socketcan::CanSocket socket_;
  std::vector<CanReceiveHandler> handlers_;
  socketcan::BusStateTracker tracker_;
  std::uint64_t frames_ = 0;
  std::uint64_t error_frames_ = 0;
  std::uint64_t send_failures_ = 0;
};

} // namespace hilrig::far
