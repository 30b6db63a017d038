#include "rig/results/merge.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "rig/results/results_json.hpp"

namespace hilrig::rig {

namespace {

// "shard 1 (b/results.json)": how a message names a shard, with its file when known.
std::string shard_name(const CampaignResult& s, const std::string& file) {
  return file.empty() ? fmt::format("shard {}", s.shard.index)
                      : fmt::format("shard {} ({})", s.shard.index, file);
}

// The board and station a shard ran on, as a message quotes them ("" reads "none").
std::string quoted(const std::string& v) { return v.empty() ? "none" : fmt::format("'{}'", v); }

} // namespace

CampaignResult merge_shards(std::vector<CampaignResult> shards, const std::vector<std::string>& files) {
  if (shards.empty()) throw std::invalid_argument("no shards given");
  if (!files.empty() && files.size() != shards.size())
    throw std::invalid_argument(
        fmt::format("{} shard files named for {} shards", files.size(), shards.size()));
  std::vector<std::string> names(shards.size());
  for (std::size_t i = 0; i < shards.size(); ++i)
    names[i] = shard_name(shards[i], files.empty() ? "" : files[i]);
  std::vector<std::size_t> order(shards.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return shards[a].shard.index < shards[b].shard.index;
  });
  std::vector<CampaignResult> sorted;
  std::vector<std::string> sorted_names;
  for (std::size_t i : order) {
    sorted.push_back(std::move(shards[i]));
    sorted_names.push_back(names[i]);
  }
  shards = std::move(sorted);
  const CampaignResult& first = shards.front();
  const std::string& first_name = sorted_names.front();
  const auto count = first.shard.count;
  std::map<std::uint32_t, std::size_t> seen; // shard index -> the position of the shard that holds it
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const CampaignResult& s = shards[i];
    const std::string& name = sorted_names[i];
    if (s.campaign != first.campaign || s.device != first.device || s.seed != first.seed) {
      throw std::invalid_argument(
          fmt::format("{} is from campaign '{}' ({}, seed {}), not '{}' ({}, seed {})", name, s.campaign,
                      s.device, s.seed, first.campaign, first.device, first.seed));
    }
    if (s.campaign_sha256 != first.campaign_sha256 || s.tool_version != first.tool_version) {
      throw std::invalid_argument(fmt::format(
          "{} ran campaign file sha256 {} with hilrig {}, {} ran sha256 {} "
          "with hilrig {}: "
          "shards of different campaign revisions or tool versions do not merge",
          name, s.campaign_sha256, s.tool_version, first_name, first.campaign_sha256, first.tool_version));
    }
    // Shards of one result are one board at one station: runs of two boards (or two benches)
    // merged would read as one board's complete campaign.
    if (s.dut_serial != first.dut_serial || s.station != first.station) {
      throw std::invalid_argument(
          fmt::format("{} ran on DUT serial {} at station {}, {} on DUT serial {} at station {}: "
                      "shards of different boards ([dut] serial) or stations (--station) do not merge",
                      name, quoted(s.dut_serial), quoted(s.station), first_name, quoted(first.dut_serial),
                      quoted(first.station)));
    }
    if (s.trace_policy != first.trace_policy) {
      // The merged result says which runs kept traces: one policy for all, or it would mislead.
      throw std::invalid_argument(fmt::format("{} ran with --trace {}, {} with --trace {}: "
                                              "shards of different trace policies do not merge",
                                              name, to_string(s.trace_policy), first_name,
                                              to_string(first.trace_policy)));
    }
    if (s.shard.count != count) {
      throw std::invalid_argument(fmt::format("{} is one of {} shards, {} one of {}: shard counts differ",
                                              name, s.shard.count, first_name, count));
    }
    if (const auto [at, added] = seen.emplace(s.shard.index, i); !added) {
      throw std::invalid_argument(
          fmt::format("shard {} given twice: {} and {}", s.shard.index, sorted_names[at->second], name));
    }
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!seen.contains(i)) throw std::invalid_argument(fmt::format("shard {} of {} is missing", i, count));
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
  out.trace_policy = first.trace_policy;
  out.shard = Shard{0, 1};
  out.started_at = first.started_at;
  out.host = first.host;
  std::map<std::uint64_t, std::size_t> indices; // run index -> the position of the shard that holds it
  for (std::size_t i = 0; i < shards.size(); ++i) {
    CampaignResult& s = shards[i];
    out.planned_runs += s.planned_runs;
    if (s.interrupted && !out.interrupted) out.interrupted = s.interrupted; // a shard stopped early
    for (auto& run : s.runs) {
      // Shard K of N runs the runs whose index mod N is K (docs/ci.md); any other index in it
      // is not one this shard ran.
      if (run.index % count != s.shard.index)
        throw std::invalid_argument(
            fmt::format("run {} in {}: shard {} of {} holds the runs whose index mod {} is {}", run.index,
                        sorted_names[i], s.shard.index, count, count, s.shard.index));
      // Two shards cannot both hold a run (each holds its own residue, above): a run twice is
      // twice in one shard file.
      if (const auto [at, added] = indices.emplace(run.index, i); !added)
        throw std::invalid_argument(fmt::format("run {} appears twice in {}", run.index, sorted_names[i]));
      out.runs.push_back(std::move(run));
    }
  }
  // Every index a run of the campaign's plan can have: 0 .. planned - 1.
  for (const auto& [index, at] : indices)
    if (index >= out.planned_runs)
      throw std::invalid_argument(
          out.planned_runs == 0
              ? fmt::format("run {} in {}: the campaign plans no runs", index, sorted_names[at])
              : fmt::format("run {} in {}: the campaign plans {} runs, 0 .. {}", index, sorted_names[at],
                            out.planned_runs, out.planned_runs - 1));
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
