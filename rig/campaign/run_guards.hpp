#pragma once
// Guards that make every virtual run end: a model that keeps scheduling events at one
// instant (virtual time no longer advances) or floods the trace is stopped with a named rig
// fault instead of running for ever or filling the disk.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "core/time.hpp"

namespace hilrig::campaign {

struct RunGuards {
  // Events processed at one virtual instant before the run counts as stalled. A busy
  // instant holds a few hundred (every line of every board changing at once); a model
  // that reschedules itself at `now` holds them for ever.
  std::uint64_t max_events_per_instant = 1'000'000;
  // Trace samples (edges and values) a run may record, spilled ones included: ~20 bytes of
  // VCD each, so the default bounds trace.vcd near 2 GB. The shipped campaigns record
  // well under 10^6.
  std::size_t max_trace_samples = 100'000'000;
};

// Watches one run: call before each event with the time of that event and the trace's
// sample count. Returns the rig fault (naming the guard) once a limit is passed.
class ProgressGuard {
public:
  explicit ProgressGuard(const RunGuards& guards) : guards_(guards) {}
  // Inline: it runs before every event, and only a tripped guard formats its fault.
  [[nodiscard]] std::optional<std::string> check(Nanos event_time, std::size_t trace_samples) {
    if (event_time != instant_) {
      instant_ = event_time;
      events_at_instant_ = 0;
    }
    if (++events_at_instant_ > guards_.max_events_per_instant || trace_samples > guards_.max_trace_samples)
      return tripped();
    return std::nullopt;
  }

private:
  [[nodiscard]] std::string tripped() const;

  RunGuards guards_;
  Nanos instant_{Nanos::min()};
  std::uint64_t events_at_instant_ = 0;
};

} // namespace hilrig::campaign
