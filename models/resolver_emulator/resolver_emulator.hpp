#pragma once
// The resolver-emulator CAN node (DESIGN "Backends"): on a real rig, resolver stator signals
// come from this node. It receives ResolverAngle frames (0x120, signals/resolver_frames.hpp,
// rt-config/can/hilrig-frontend.dbc), holds each frame's angle at the frame's receive time
// (end of frame), advances it at the frame's speed until the next frame, and drives
//   reference(t) = A * sin(2*pi*f*t + phase),
//   SIN(t) = TR * reference(t) * sin(theta(t)),   COS(t) = TR * reference(t) * cos(theta(t)).
// A frame with valid = 0 drives both stators to zero (safe state); sin_open / cos_open open
// that winding. No frame for `timeout_periods` frame periods: both stators drop to zero and
// the timeout is reported, until the next frame.
//
// The outputs are Waveforms (functions of time) for an analog channel. They read a short
// history of received frames, so a reader may sample at any t up to a few frame periods
// before the node's latest frame, and at any t after it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "core/analog.hpp"
#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "core/time.hpp"

namespace hilrig::models::resolver_emulator {

struct ResolverEmulatorParams {
  std::uint8_t channel = 0;          // the ResolverAngle channel this node drives (0..15)
  double excitation_hz = 5'000.0;    // 2.2..7 kHz, as the resolvers the boards accept
  double excitation_amplitude = 1.0; // reference peak, V
  double excitation_phase_rad = 0.0; // reference phase at t = 0
  double transformation_ratio = 1.0; // TR, stator / reference
  Nanos frame_period = milliseconds(1);
  unsigned timeout_periods = 3; // [MODEL] no frame for 3 periods: stators to zero
};

// What the node counted, by name.
struct ResolverEmulatorCounters {
  std::uint64_t frames = 0;        // good angle frames for this channel
  std::uint64_t bad_frames = 0;    // ID 0x120 but not a standard 8-byte data frame
  std::uint64_t other_ids = 0;     // frames with another ID (ignored)
  std::uint64_t other_channel = 0; // angle frames for another channel (ignored)
  std::uint64_t sequence_gaps = 0; // frames whose sequence was not last + 1 (mod 16)
  std::uint64_t lost_frames = 0;   // frames missing in those gaps (mod 16)
  std::uint64_t timeouts = 0;      // times the frame timeout expired
};

// One received frame as the node holds it.
struct ResolverAnchor {
  Nanos received{0};        // end of frame: the instant `angle_turns` holds
  double angle_turns = 0.0; // [0, 1)
  double speed_turns_per_s = 0.0;
  bool valid = true;
  bool sin_open = false;
  bool cos_open = false;
};

class ResolverEmulator {
public:
  using TimeoutHandler = std::function<void(Nanos at)>;
  using FrameHandler = std::function<void()>;

  // Attaches to `port` (the node's side of the bus). Throws std::invalid_argument for an
  // excitation outside 2.2..7 kHz, a non-positive amplitude, TR or frame period, a channel
  // above 15, or timeout_periods 0. The scheduler must outlive the node.
  ResolverEmulator(Scheduler& scheduler, CanPort& port, ResolverEmulatorParams params);
  ResolverEmulator(const ResolverEmulator&) = delete;
  ResolverEmulator& operator=(const ResolverEmulator&) = delete;
  ~ResolverEmulator();

  [[nodiscard]] const ResolverEmulatorParams& params() const;
  [[nodiscard]] const ResolverEmulatorCounters& counters() const;
  // True from a timeout until the next good frame.
  [[nodiscard]] bool timed_out() const;
  [[nodiscard]] std::optional<ResolverAnchor> last_frame() const;
  // Takes `frame` as received now, off the bus: the frame a rig's stream delivered before a
  // run began (a rig streams the shaft between runs; without it the stators would carry
  // nothing until the run's first frame is received, a frame time into the run).
  void hold(const CanFrame& frame) { receive(frame, scheduler_.now()); }

  // Called when the frame timeout expires, with its time.
  void on_timeout(TimeoutHandler handler);
  // Called after each frame the node takes: from then on its angle may differ from what it
  // interpolated before (a reader sampling ahead of time reads again).
  void on_frame(FrameHandler handler);

  // The interpolated angle in turns (wrapped to [0, 1)) at t, or empty when the node does
  // not drive its stators then (no frame yet, frame invalid, or timed out).
  [[nodiscard]] std::optional<double> angle_turns(Nanos t) const;
  [[nodiscard]] double reference(Nanos t) const;
  [[nodiscard]] double sin(Nanos t) const;
  [[nodiscard]] double cos(Nanos t) const;

  // The outputs for analog channels. They share the node's state and stay valid after the
  // node is destroyed (then holding its last frames).
  [[nodiscard]] Waveform reference_waveform() const;
  [[nodiscard]] Waveform sin_waveform() const;
  [[nodiscard]] Waveform cos_waveform() const;

private:
  struct State;
  void receive(const CanFrame& frame, Nanos at);
  void arm_timeout(Nanos last_frame);

  Scheduler& scheduler_;
  std::shared_ptr<State> state_;
  EventId timeout_event_{};
  TimeoutHandler timeout_handler_;
  FrameHandler frame_handler_;
  // The port's receive handler outlives the node (CanPort has no detach): it checks this.
  std::shared_ptr<ResolverEmulator*> self_;
};

} // namespace hilrig::models::resolver_emulator
