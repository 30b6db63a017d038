#pragma once
// Where a wake-up's time goes, for `hilrig latency --breakdown`: the measuring loop stamps
// each wake-up with CLOCK_MONOTONIC reads into an array made (and touched) before it starts,
// and the stamps are summarised after the run. What it separates: the latency itself (the
// kernel and the machine), the loop's own work between waking and going back to sleep (what
// cyclictest does too: a histogram update and the next deadline), and what a clock read
// costs (the trace adds two a wake-up, so its own cost is reported beside it).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/time.hpp"

namespace hilrig::rig {

struct WakeupStamps {
  Nanos due;    // the absolute time the loop asked to wake at
  Nanos asleep; // clock read just before clock_nanosleep
  Nanos woke;   // the loop's own clock read after it returned
  Nanos done;   // clock read after the histogram update and the next deadline
};

class WakeupTrace {
public:
  // Room for `capacity` wake-ups, allocated and written once here so the loop touches no
  // new page; wake-ups beyond it are counted, not stored.
  explicit WakeupTrace(std::size_t capacity);

  void add(const WakeupStamps& s) noexcept {
    if (size_ < stamps_.size()) {
      stamps_[size_++] = s;
    } else {
      ++dropped_;
    }
  }
  [[nodiscard]] std::span<const WakeupStamps> stamps() const noexcept { return {stamps_.data(), size_}; }
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_; }

private:
  std::vector<WakeupStamps> stamps_;
  std::size_t size_ = 0;
  std::uint64_t dropped_ = 0;
};

// Nearest-rank percentiles of one quantity: the smallest sample with at least q of all
// samples at or below it (the rule LatencyHistogram::percentile_us applies to 1 us bins).
struct Spread {
  Nanos p50{0};
  Nanos p99{0};
  Nanos max{0};
};
Spread spread_of(std::vector<Nanos> samples);

struct WakeupBreakdown {
  std::size_t wakeups = 0;
  Spread latency; // woke - due
  Spread work;    // done - woke: the loop's work per wake-up (plus one clock read)
  Spread ahead;   // due - asleep: how long before the deadline the loop was back asleep
};
WakeupBreakdown summarize(std::span<const WakeupStamps> stamps);

// Back-to-back CLOCK_MONOTONIC reads, `pairs` times: what one read costs on this machine.
Spread clock_read_cost(std::size_t pairs);

} // namespace hilrig::rig
