#pragma once
// A subset of a campaign's checks (`hilrig run --only NAME --tag T`): the checks named, and
// those tagged (`[[check]] tags = [...]`), are kept in every scenario; the rest are dropped.
// A fault whose must-catch checks are all dropped cannot be judged, so its runs are dropped
// too. The runs are planned again.

#include <cstddef>
#include <string>
#include <vector>

#include "rig/campaign/campaign.hpp"

namespace hilrig::campaign {

struct CheckSelection {
  std::vector<std::string> only; // check names
  std::vector<std::string> tags;
  [[nodiscard]] bool all() const { return only.empty() && tags.empty(); }
};

// Every check name and tag the campaign has, sorted: what --only and --tag can name.
[[nodiscard]] std::vector<std::string> check_names(const Campaign& c);
[[nodiscard]] std::vector<std::string> check_tags(const Campaign& c);

// Keeps the selected checks; returns how many of the first scenario's checks were kept (0: the
// selection names nothing in this campaign, and the campaign has nothing to run).
std::size_t select_checks(Campaign& c, const CheckSelection& selection);

} // namespace hilrig::campaign
