#pragma once
// The index report of a suite (`hilrig run DIR`): one self-contained page, one row per
// campaign in suite order, its verdict and totals, linking the campaign's own report.html.
// No wall-clock fields: the same suite and seeds give the same page.

#include <optional>
#include <string>
#include <vector>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

struct SuiteRow {
  std::string file;                     // the campaign file
  std::string subdir;                   // its outputs, relative to the index
  int exit_status = 0;                  // hilrig's exit status for this campaign
  std::optional<CampaignResult> result; // nullopt: nothing was written (the reason in `message`)
  std::string message;
};

[[nodiscard]] std::string to_suite_index_html(const std::string& title, const std::vector<SuiteRow>& rows,
                                              int exit_status);

} // namespace hilrig::rig
