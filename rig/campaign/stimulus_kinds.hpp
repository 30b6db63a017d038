#pragma once
// The registry of stimulus kinds a campaign can schedule, signal faults among them.
// The parser takes kind names from here and `hilrig list` prints it.

#include <span>
#include <string_view>

#include "rig/campaign/campaign.hpp"

namespace hilrig::campaign {

struct StimulusKindInfo {
  std::string_view name; // as written: kind = "glitch"
  StimulusKind kind;
  bool signal_fault;     // may be a [[fault]]'s signal
  std::string_view keys; // the keys it takes besides kind, at and line
  std::string_view summary;
};

[[nodiscard]] std::span<const StimulusKindInfo> stimulus_kinds();
[[nodiscard]] const StimulusKindInfo* find_stimulus_kind(std::string_view name);

} // namespace hilrig::campaign
