#pragma once
// A raw SocketCAN socket: classic and CAN FD frames, receive filters, error frames, kernel
// receive timestamps (SO_TIMESTAMPING, software: CLOCK_REALTIME, as candump logs them), the
// socket's receive-queue drop counter (SO_RXQ_OVFL), and transmit with a deadline. Frames go
// out and come in a batch per syscall (sendmmsg/recvmmsg) into buffers made once at
// construction: send and receive never allocate, so the RT side may use them.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/can_frame.hpp"
#include "core/time.hpp"
#include "drivers/socketcan/batch_send.hpp"
#include "drivers/socketcan/bus_state.hpp"
#include "drivers/socketcan/raw_frame.hpp"

namespace hilrig::socketcan {

struct CanFilter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0; // bits that must match; 0 accepts everything
  bool extended = false;
};

struct CanSocketOptions {
  bool fd = false;                // accept and send CAN FD frames
  std::vector<CanFilter> filters; // empty: receive everything (unless !data_frames)
  bool data_frames = true;        // false: no data frame at all, only error frames
  bool error_frames = true;       // receive controller error frames
  bool receive_own = false;       // see our own transmitted frames
};

// A failure to open or configure the socket; names the interface and the reason.
class CanError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class CanSocket {
public:
  // Frames per sendmmsg/recvmmsg: a burst of this many costs one syscall.
  static constexpr std::size_t kBatch = 64;

  CanSocket(const std::string& interface, const CanSocketOptions& options = {});
  ~CanSocket();
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;

  // Queues a frame, waiting for room in the transmit queue until `deadline`
  // (CLOCK_MONOTONIC, absolute). A frame that could not be queued in time is not sent.
  SendStatus send(const CanFrame& frame, Nanos deadline);
  // Queues `frames` in order, up to kBatch per sendmmsg(2), waiting for room until
  // `deadline` as send() does. Frames [0, sent) were queued; the rest were not (status says
  // why: an FD frame on a classic socket stops the run there, Failed with EINVAL).
  BatchSent send_batch(std::span<const CanFrame> frames, Nanos deadline);

  // One received frame or error frame, waiting at most `timeout` (0: do not wait).
  std::optional<CanReceived> receive(Nanos timeout = Nanos{0});
  // Whatever is queued, up to out.size() (at most kBatch) frames in one recvmmsg(2), each
  // with its own kernel timestamp; waits at most `timeout` only when nothing is queued.
  // Returns how many were written to `out` (0: none in time, or an error: last_errno()).
  std::size_t receive_batch(std::span<CanReceived> out, Nanos timeout = Nanos{0});

  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] const std::string& interface() const { return interface_; }
  [[nodiscard]] int last_errno() const { return last_errno_; }
  // Frames the kernel dropped because this socket's receive queue was full. SO_RXQ_OVFL
  // brings the count only on a frame queued after a drop (none comes while the queue stays
  // full), so the kernel's counter itself is read too (SO_MEMINFO). No allocation.
  [[nodiscard]] std::uint32_t rx_queue_drops() const;

private:
  struct Buffers; // the batch's frames, iovecs, headers and control space

  int fd_ = -1;
  std::uint32_t rx_queue_drops_ = 0;
  std::string interface_;
  bool fd_frames_ = false;
  int last_errno_ = 0;
  std::unique_ptr<Buffers> io_;
};

} // namespace hilrig::socketcan
