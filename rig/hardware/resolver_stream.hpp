#pragma once
// The resolver angle stream of a hardware run on its own real-time thread (SCHED_FIFO at
// rt.resolver_priority, pinned to rt.resolver_cpu, memory locked: docs/rig-config.md), apart
// from the host link's thread, whose Modbus transactions block for milliseconds. Like the RT
// loop it allocates nothing while it plays: each frame is built on the stack at its period
// boundary, the controller's reports are read before it goes out, and the sent frames go to
// a lock-free ring the recording thread drains for can.log.

#include <atomic>
#include <cstdint>
#include <string>

#include "core/can_frame.hpp"
#include "core/time.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "rig/hardware/rig_ports.hpp"
#include "rig/rt/spsc_ring.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::hardware {

struct SentFrame {
  Nanos at; // when it was handed to the interface, from the run's start
  CanFrame frame;
};

struct ResolverStreamStats {
  std::uint64_t sent = 0;
  std::int64_t stale = 0;           // frames skipped because the thread woke more than a period late
  std::uint64_t ring_overflows = 0; // sent frames the recording side was too slow to take
};

// Sends the angle frame of every period boundary t (0, period, ... up to `end`, from the
// absolute CLOCK_MONOTONIC `start`) until `end` or `stop`. A frame more than a period late
// would tell the front end an angle the shaft has already left: the stream skips to the next
// boundary after now and counts the skipped ones as stale. Returns the rig fault that ended
// the stream (ResolverCan::send or check), "" when none; reads the controller's reports once
// more at the end so overruns of the last period are counted.
[[nodiscard]] std::string play_resolver_stream(const signals::MotionProfile& profile,
                                               const models::resolver_emulator::AngleStreamParams& params,
                                               Nanos end, ResolverCan& can, Nanos start,
                                               rig::SpscRing<SentFrame>& sent, const std::atomic<bool>& stop,
                                               ResolverStreamStats& stats);

} // namespace hilrig::hardware
