#pragma once
// Merging shards: the results of shards 0..N-1 of one campaign into one result equal to the
// unsharded run (runs ordered by run index; faults, totals and verdict recomputed).

#include <string>
#include <vector>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

// Throws std::invalid_argument when the shards belong to different campaigns, devices, seeds,
// campaign revisions, tool versions, boards (`[dut] serial`), stations (`--station`), trace
// policies (`--trace`) or shard counts, when a shard is missing or given twice, or when two shards hold the
// same run index. `files` (one per shard, in the order given; may be empty) names each shard in the messages.
// Wall-clock fields come from shard 0.
[[nodiscard]] CampaignResult merge_shards(std::vector<CampaignResult> shards,
                                          const std::vector<std::string>& files = {});

// Equal content, ignoring the wall-clock fields: what "equal to the unsharded run" means.
[[nodiscard]] bool same_content(const CampaignResult& a, const CampaignResult& b);

} // namespace hilrig::rig
