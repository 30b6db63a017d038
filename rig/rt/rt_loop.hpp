#pragma once
// The RT loop only executes (DESIGN.md, idea 6): it plays a precomputed edge schedule on
// output lines at absolute CLOCK_MONOTONIC times, drains timestamped input edges, and
// hands every sample to the non-RT side through a lock-free ring. Inside play() there is
// no allocation, lock or log; the only syscalls are clock_nanosleep and the ports' I/O.

#include <atomic>
#include <cstdint>
#include <span>

#include "core/line.hpp"
#include "core/rt_ports.hpp"
#include "core/time.hpp"
#include "rig/rt/latency_histogram.hpp"
#include "rig/rt/spsc_ring.hpp"
#include "rig/rt/wakeup_trace.hpp"

namespace hilrig::rig {

using hilrig::InputEdge;
using hilrig::RtInputPort;
using hilrig::RtOutputPort;
using hilrig::ScheduledEdge;

struct LoopSample {
  enum class Kind : std::uint8_t { Output, Input };
  Kind kind;
  std::uint16_t line;
  Level level;
  Nanos scheduled; // Output: when it was due (absolute); Input: == actual
  Nanos actual;    // Output: after the write returned; Input: the backend's timestamp
};

struct RtLoopConfig {
  Nanos tolerance{50'000};    // an output edge later than this is a missed deadline
  Nanos poll_period{500'000}; // longest sleep without draining inputs
};

struct RtLoopStats {
  LatencyHistogram wakeups; // wake time minus the time asked for
  std::uint64_t edges_played = 0;
  std::uint64_t inputs_seen = 0;
  std::uint64_t missed_deadlines = 0; // output edges later than the tolerance
  std::uint64_t ring_overflows = 0;   // samples the non-RT side was too slow to take
  Nanos max_edge_error{0};
  bool stopped_early = false;
};

// CLOCK_MONOTONIC now (a vDSO read: no syscall on the RT path).
Nanos monotonic_now() noexcept;

// Sleeps until an absolute CLOCK_MONOTONIC time (retrying on EINTR) and returns the time
// it woke at.
Nanos sleep_until(Nanos deadline) noexcept;

// Plays `schedule` (sorted by time) starting at absolute time `start`. `stats` must be
// preallocated by the caller (it is large); `stop` is checked every wake.
void play(std::span<const ScheduledEdge> schedule, Nanos start, RtOutputPort& outputs, RtInputPort* inputs,
          SpscRing<LoopSample>& ring, const std::atomic<bool>& stop, const RtLoopConfig& config,
          RtLoopStats& stats) noexcept;

// After the schedule: keeps draining input edges into `ring` every `poll_period` until the
// absolute time `end` or `stop`. Same rules as play(): no allocation, only sleeps and reads.
void capture_until(Nanos end, RtInputPort& inputs, SpscRing<LoopSample>& ring, const std::atomic<bool>& stop,
                   Nanos poll_period, RtLoopStats& stats) noexcept;

// Wakes every `interval` from `start` for `loops` wake-ups, measuring latency only: what
// `hilrig latency` and cyclictest both measure, and per wake-up only what cyclictest does
// (one clock read, a histogram update, the next deadline; after a stall, the next point of
// the grid, as cyclictest). `trace`, when given, also gets each wake-up's stamps (two more
// clock reads a wake-up).
void measure_wakeups(Nanos start, Nanos interval, std::uint64_t loops, const std::atomic<bool>& stop,
                     LatencyHistogram& histogram, WakeupTrace* trace = nullptr) noexcept;

} // namespace hilrig::rig
