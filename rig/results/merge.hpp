#pragma once
// Merging shards: the results of shards 0..N-1 of one campaign into one result equal to the
// unsharded run (runs ordered by run index; faults, totals and verdict recomputed).

#include <vector>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

// Throws std::invalid_argument when the shards belong to different campaigns, devices, seeds
// or shard counts, when a shard is missing or given twice, or when two shards hold the same
// run index. Wall-clock fields come from shard 0.
[[nodiscard]] CampaignResult merge_shards(std::vector<CampaignResult> shards);

// Equal content, ignoring the wall-clock fields: what "equal to the unsharded run" means.
[[nodiscard]] bool same_content(const CampaignResult& a, const CampaignResult& b);

} // namespace hilrig::rig
