#pragma once
// The nightly trend: one self-contained HTML page with each measurement's value against its
// limits over the nights (the slow drift a lab watches before it becomes a failure).

#include <span>
#include <string>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

// One night: its results and the label it is shown under (its start time, or its file).
struct Night {
  const CampaignResult* result = nullptr;
  std::string label;
  std::string file{}; // where it was read from: messages name it (nights can share a label)
};

// The page for `nights`, oldest first. A measurement is named by its run and its name; a night
// that did not measure it leaves a gap. The limits drawn are the last night's. Throws
// std::invalid_argument when the nights are not all the same campaign on the same device.
[[nodiscard]] std::string to_trend_html(std::span<const Night> nights);

} // namespace hilrig::rig
