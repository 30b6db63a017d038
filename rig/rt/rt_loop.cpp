#include "rig/rt/rt_loop.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <ctime>

namespace hilrig::rig {

namespace {

void drain_inputs(RtInputPort& inputs, SpscRing<LoopSample>& ring, RtLoopStats& stats) noexcept {
  std::array<InputEdge, 64> batch{};
  for (;;) {
    const std::size_t n = inputs.poll(batch);
    for (std::size_t k = 0; k < n; ++k) {
      const InputEdge& e = batch[k];
      ++stats.inputs_seen;
      if (!ring.push(LoopSample{LoopSample::Kind::Input, e.line, e.level, e.time, e.time})) {
        ++stats.ring_overflows;
      }
    }
    if (n < batch.size()) return;
  }
}

} // namespace

Nanos monotonic_now() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

Nanos sleep_until(Nanos deadline) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline.count() / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline.count() % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
  return monotonic_now();
}

void capture_until(Nanos end, RtInputPort& inputs, SpscRing<LoopSample>& ring, const std::atomic<bool>& stop,
                   Nanos poll_period, RtLoopStats& stats) noexcept {
  for (;;) {
    drain_inputs(inputs, ring, stats);
    const Nanos now = monotonic_now();
    if (now >= end || stop.load(std::memory_order_relaxed)) return;
    (void)sleep_until(std::min(end, now + poll_period));
  }
}

void play(std::span<const ScheduledEdge> schedule, Nanos start, RtOutputPort& outputs, RtInputPort* inputs,
          SpscRing<LoopSample>& ring, const std::atomic<bool>& stop, const RtLoopConfig& config,
          RtLoopStats& stats) noexcept {
  std::size_t next = 0;
  Nanos last_poll = start;
  while (next < schedule.size()) {
    if (stop.load(std::memory_order_relaxed)) {
      stats.stopped_early = true;
      return;
    }
    const Nanos due = start + schedule[next].time;
    // Wake for the next edge, or earlier to drain inputs when the gap is long.
    const Nanos wake_at =
        (inputs != nullptr && due - last_poll > config.poll_period) ? last_poll + config.poll_period : due;
    const Nanos woke = sleep_until(wake_at);
    stats.wakeups.record(woke - wake_at);
    // Every edge due by now goes out in this wake-up (A/B/Z edges at one time together).
    while (next < schedule.size() && start + schedule[next].time <= woke) {
      const ScheduledEdge& e = schedule[next];
      outputs.write(e.line, e.level);
      const Nanos written = monotonic_now();
      const Nanos when = start + e.time;
      const Nanos error = written - when;
      if (error > stats.max_edge_error) stats.max_edge_error = error;
      if (error > config.tolerance) ++stats.missed_deadlines;
      ++stats.edges_played;
      if (!ring.push(LoopSample{LoopSample::Kind::Output, e.line, e.level, when, written})) {
        ++stats.ring_overflows;
      }
      ++next;
    }
    if (inputs != nullptr) {
      drain_inputs(*inputs, ring, stats);
      last_poll = woke;
    }
  }
  if (inputs != nullptr) drain_inputs(*inputs, ring, stats);
}

void measure_wakeups(Nanos start, Nanos interval, std::uint64_t loops, const std::atomic<bool>& stop,
                     LatencyHistogram& histogram, WakeupTrace* trace) noexcept {
  Nanos next = start + interval;
  for (std::uint64_t i = 0; i < loops && !stop.load(std::memory_order_relaxed); ++i) {
    const Nanos asleep = trace != nullptr ? monotonic_now() : Nanos{0};
    const Nanos due = next;
    const Nanos woke = sleep_until(due);
    histogram.record(woke - due);
    // After a stall, the next point of the grid still ahead (as cyclictest): no burst of late
    // wake-ups, and the phase is kept.
    next += interval;
    while (next < woke) next += interval;
    if (trace != nullptr) trace->add(WakeupStamps{due, asleep, woke, monotonic_now()});
  }
}

} // namespace hilrig::rig
