#pragma once
// The rig side of the resolver-emulator link: sends a ResolverAngle frame (0x120,
// signals/resolver_frames.hpp) every period with the profile's angle and speed, so the
// node (resolver_emulator.hpp) can interpolate between frames.
//
// The frame sent at t carries the profile at t + lead. The node holds a frame's angle at
// its end of frame, so a lead equal to the frame's time on the bus (start of frame to end
// of frame, ~108..130 bits) cancels the transport delay; with lead 0 the node's angle lags
// the profile by that time.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "core/time.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::models::resolver_emulator {

struct AngleStreamParams {
  std::uint8_t channel = 0; // 0..15
  Nanos period = milliseconds(1);
  double units_per_turn = 1.0; // the profile's position unit (e.g. 4096 for ANS1 counts)
  Nanos lead{0};               // the frame at t carries the profile at t + lead
};

// What a ResolverAngle frame says besides the angle.
struct AngleFlags {
  bool valid = true;
  bool sin_open = false;
  bool cos_open = false;
};

// The shaft at an instant, in the stream's units (position, and speed per second).
struct ShaftSample {
  double position = 0.0;
  double velocity = 0.0;
};
// The shaft a stream reads: a motion profile, or a plant's motion as it happens.
using ShaftSource = std::function<ShaftSample(Nanos)>;

// The n-th frame of a stream, carrying `shaft`.
[[nodiscard]] CanFrame angle_frame(const ShaftSample& shaft, const AngleStreamParams& params, std::uint64_t n,
                                   AngleFlags flags = {});
// The frame the stream sends at t as its n-th frame: the profile at t + lead. Allocates
// nothing, so a real-time thread may build its frames with it.
[[nodiscard]] CanFrame angle_frame(const signals::MotionProfile& profile, const AngleStreamParams& params,
                                   Nanos t, std::uint64_t n, AngleFlags flags = {});

class AngleStreamer {
public:
  // Throws std::invalid_argument for a period <= 0, units_per_turn <= 0 or a channel above 15.
  // The scheduler and the port must outlive the streamer.
  AngleStreamer(Scheduler& scheduler, CanPort& port, signals::MotionProfile profile,
                AngleStreamParams params = {});
  AngleStreamer(Scheduler& scheduler, CanPort& port, ShaftSource shaft, AngleStreamParams params = {});
  AngleStreamer(const AngleStreamer&) = delete;
  AngleStreamer& operator=(const AngleStreamer&) = delete;
  ~AngleStreamer();

  // First frame at `first` (>= now), then one every period until stop().
  void start(Nanos first);
  void stop();
  [[nodiscard]] bool running() const { return next_.valid(); }

  // The time from a frame's send to the instant the node holds its angle (its end of frame),
  // when the sender knows it (a virtual bus), and every value it can take: each frame then
  // carries the shaft at that instant, params.lead aside, so the node's angle does not lag the
  // shaft by the transport. The delay hangs on the frame's stuff bits, so on the angle it
  // carries: each frame is the one built for a delay in `possible` that is its own delay, its
  // angle the code at or above the shaft or up to 15 codes (1/2^24 turn each) above, whichever
  // first gives a frame that long (the nearest miss when none does).
  using TransportDelay = std::function<Nanos(const CanFrame&)>;
  void lead_by_transport(TransportDelay delay, std::vector<Nanos> possible);

  // Flags carried by the frames sent from now on.
  void set_valid(bool valid) { flags_.valid = valid; }
  void set_open_windings(bool sin_open, bool cos_open) {
    flags_.sin_open = sin_open;
    flags_.cos_open = cos_open;
  }

  [[nodiscard]] std::uint64_t frames_sent() const { return sent_; }
  [[nodiscard]] const AngleStreamParams& params() const { return params_; }

private:
  void send_at(Nanos t);

  Scheduler& scheduler_;
  [[nodiscard]] CanFrame frame_at(Nanos t);

  CanPort& port_;
  ShaftSource shaft_;
  AngleStreamParams params_;
  TransportDelay transport_;
  std::vector<Nanos> possible_;
  Nanos last_delay_{0}; // the last frame's transport delay

  // frame_at's tries for one delay: the shaft at it, the angle's code at or above the shaft,
  // and the own delay of each code's frame tried so far (bit n of `known`: code + n).
  static constexpr int kNudges = 16; // codes tried from the one at or above the shaft
  struct DelayTry {
    Nanos delay{0};
    ShaftSample shaft;
    double code = 0.0;
    std::uint16_t known = 0;
    std::array<Nanos, kNudges> own{};
  };
  std::vector<DelayTry> tries_; // this frame's, kept for its capacity

  EventId next_{};
  std::uint64_t sent_ = 0;
  AngleFlags flags_;
};

} // namespace hilrig::models::resolver_emulator
