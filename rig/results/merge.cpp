#include "rig/results/merge.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "rig/results/results_json.hpp"

namespace hilrig::rig {

CampaignResult merge_shards(std::vector<CampaignResult> shards) {
  if (shards.empty()) throw std::invalid_argument("merge: no shards given");
  std::sort(shards.begin(), shards.end(),
            [](const CampaignResult& a, const CampaignResult& b) { return a.shard.index < b.shard.index; });
  const CampaignResult& first = shards.front();
  const auto count = first.shard.count;
  std::set<std::uint32_t> seen;
  for (const auto& s : shards) {
    if (s.campaign != first.campaign || s.device != first.device || s.seed != first.seed) {
      throw std::invalid_argument(
          fmt::format("merge: shard {} is from campaign '{}' ({}, seed {}), not '{}' ({}, seed {})",
                      s.shard.index, s.campaign, s.device, s.seed, first.campaign, first.device, first.seed));
    }
    if (s.campaign_sha256 != first.campaign_sha256 || s.tool_version != first.tool_version) {
      throw std::invalid_argument(
          fmt::format("merge: shard {} ran campaign file sha256 {} with hilrig {}, shard {} ran sha256 {} "
                      "with hilrig {}: "
                      "shards of different campaign revisions or tool versions do not merge",
                      s.shard.index, s.campaign_sha256, s.tool_version, first.shard.index,
                      first.campaign_sha256, first.tool_version));
    }
    if (s.shard.count != count) {
      throw std::invalid_argument(
          fmt::format("merge: shard counts differ ({} and {})", s.shard.count, count));
    }
    if (!seen.insert(s.shard.index).second) {
      throw std::invalid_argument(fmt::format("merge: shard {} given twice", s.shard.index));
    }
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!seen.contains(i))
      throw std::invalid_argument(fmt::format("merge: shard {} of {} is missing", i, count));
  }
  CampaignResult out;
  out.campaign = first.campaign;
  out.device = first.device;
  out.campaign_sha256 = first.campaign_sha256;
  out.tool_version = first.tool_version;
  out.seed = first.seed;
  out.campaign_file = first.campaign_file;
  out.dut_serial = first.dut_serial;
  out.station = first.station;
  out.host_link = first.host_link;
  out.backend = first.backend;
  out.shard = Shard{0, 1};
  out.started_at = first.started_at;
  out.host = first.host;
  std::set<std::uint64_t> indices;
  for (auto& s : shards) {
    out.planned_runs += s.planned_runs;
    if (s.interrupted && !out.interrupted) out.interrupted = s.interrupted; // a shard stopped early
    for (auto& run : s.runs) {
      if (!indices.insert(run.index).second) {
        throw std::invalid_argument(fmt::format("merge: run {} appears in two shards", run.index));
      }
      out.runs.push_back(std::move(run));
    }
  }
  finalize(out);
  return out;
}

bool same_content(const CampaignResult& a, const CampaignResult& b) {
  auto ja = to_json(a);
  auto jb = to_json(b);
  ja.erase("wall_clock");
  jb.erase("wall_clock");
  return ja == jb;
}

} // namespace hilrig::rig
