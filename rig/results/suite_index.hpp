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

// hilrig's exit status in words (rig/cli/exit_status.hpp). Exit 1 is worded by the verdict
// behind it: "a check failed" (fail: a check failed or a fault was not caught) or "a check
// could not be judged" (error: nothing judged, never a pass), as docs/campaigns.md's
// judgement table tells them apart. Without a verdict, exit 1 reads "a check failed".
[[nodiscard]] const char* exit_words(int status, std::optional<Outcome> verdict = std::nullopt);

// A suite's campaigns counted by what they came to, for its summary line and index page alike.
struct SuiteTally {
  std::size_t campaigns = 0, passed = 0, failed = 0, not_judged = 0, bad_input = 0, rig_fault = 0;
  // "2 campaign(s), 1 passed, 0 with a failed check, 1 with a check that could not be judged, 0 bad
  // input, 0 rig fault"
  [[nodiscard]] std::string text() const;
  // The suite's exit status in words: exit 1 by the verdicts behind it.
  [[nodiscard]] std::string exit_text(int status) const;
};
[[nodiscard]] SuiteTally tally(const std::vector<SuiteRow>& rows);

[[nodiscard]] std::string to_suite_index_html(const std::string& title, const std::vector<SuiteRow>& rows,
                                              int exit_status);

} // namespace hilrig::rig
