#include "rig/campaign/run_guards.hpp"

#include <fmt/format.h>

namespace hilrig::campaign {

std::optional<std::string> ProgressGuard::check(Nanos event_time, std::size_t trace_samples) {
  if (event_time != instant_) {
    instant_ = event_time;
    events_at_instant_ = 0;
  }
  if (++events_at_instant_ > guards_.max_events_per_instant)
    return fmt::format("virtual-time progress guard: more than {} events at one instant without time "
                       "advancing (a model that keeps rescheduling itself)",
                       guards_.max_events_per_instant);
  if (trace_samples > guards_.max_trace_samples)
    return fmt::format("trace size guard: more than {} trace samples recorded", guards_.max_trace_samples);
  return std::nullopt;
}

} // namespace hilrig::campaign
