#include "rig/campaign/run_guards.hpp"

#include <fmt/format.h>

namespace hilrig::campaign {

std::string ProgressGuard::tripped() const {
  if (events_at_instant_ > guards_.max_events_per_instant)
    return fmt::format("virtual-time progress guard: more than {} events at one instant without time "
                       "advancing (a model that keeps rescheduling itself)",
                       guards_.max_events_per_instant);
  return fmt::format("trace size guard: more than {} trace samples recorded", guards_.max_trace_samples);
}

} // namespace hilrig::campaign
