#pragma once
// A virtual CAN bus: frame durations from bitrate and bit stuffing, arbitration by
// identifier when nodes start together, error-frame and frame-loss injection hooks.

#include <cstdint>
#include <functional>
#include <string>

#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "core/trace.hpp"

namespace hilrig::virt {

struct CanBitTiming {
  std::uint32_t nominal_bitrate = 500'000;  // arbitration phase, bit/s
  std::uint32_t data_bitrate = 2'000'000;   // FD data phase when BRS is set, bit/s
};

// Bits a frame occupies on the wire, from SOF to the end of the intermission (3 bits),
// with the bits sent at the nominal and at the data bitrate counted apart.
struct CanFrameBits {
  std::uint32_t nominal = 0;
  std::uint32_t data = 0; // bits sent at the data bitrate (only FD with BRS)
  std::uint32_t stuff = 0; // stuff bits included in the two counts above
};

// Actual: stuff bits worked out from the frame's real bit stream (including its CRC).
[[nodiscard]] CanFrameBits can_frame_bits(const CanFrame& frame);
// Worst case: the maximum stuff bits any frame of this format and length could need.
[[nodiscard]] CanFrameBits can_frame_bits_worst(const CanFrame& frame);
[[nodiscard]] Nanos can_frame_duration(const CanFrameBits& bits, const CanBitTiming& timing);

class CanBus;

// One node on a virtual CAN bus (implements core CanPort).
class CanNode; // defined by the implementation; see can_bus.cpp

class CanBus {
public:
  CanBus(Scheduler& scheduler, std::string name, CanBitTiming timing, TraceRecorder* trace);
  ~CanBus();

  [[nodiscard]] const std::string& name() const;
  [[nodiscard]] const CanBitTiming& timing() const;

  // Attaches a new node; the port stays valid for the bus's lifetime.
  [[nodiscard]] CanPort& attach(std::string node_name);

  // Fault hooks, asked for each frame as it wins arbitration:
  // drop -> nobody receives it (frame loss); error -> an error frame replaces it and the
  // sender retransmits automatically (as a CAN controller does).
  using FrameFilter = std::function<bool(const CanFrame&)>;
  void set_drop(FrameFilter drop);
  void set_error(FrameFilter error);

  [[nodiscard]] std::uint64_t frames_delivered() const;
  [[nodiscard]] std::uint64_t error_frames() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace hilrig::virt
