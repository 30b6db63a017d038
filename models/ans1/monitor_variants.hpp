#pragma once
// Fault variants of the ANS1's monitors: models that are wrong on purpose, for fault-injection
// campaigns (DESIGN.md, "Fault injection is data"). ans1-core's variants.hpp maps its variant
// enum onto this struct and passes it to Monitors' constructor.
#include <string_view>

namespace hilrig::models::ans1 {

struct MonitorFaults {
  // The brake monitor measures and reports start and stop times but never raises its start or
  // stop overrun fault (its overrun outputs stay in the healthy state). A brake stop-time check
  // against the limit must catch it.
  bool brake_never_faults = false;
  // Every die-protection check detects its faults (status bits, first-to-fault) but never
  // increments the fault counter, so the fault output never drops. A DP counting check must
  // catch it.
  bool die_check_never_counts = false;
};

// Names for campaign files and reports.
inline constexpr std::string_view kBrakeNeverFaults = "brake_never_faults";
inline constexpr std::string_view kDieCheckNeverCounts = "die_check_never_counts";

} // namespace hilrig::models::ans1
