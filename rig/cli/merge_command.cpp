#include "rig/cli/merge_command.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/cli/exit_status.hpp"
#include "rig/results/merge.hpp"
#include "rig/results/results_json.hpp"

namespace hilrig::cli {
namespace {

struct MergeArgs {
  std::string out;
  std::vector<std::string> shards;
};

int run_merge(const MergeArgs& a) {
  try {
    std::vector<rig::CampaignResult> shards;
    for (const auto& path : a.shards) shards.push_back(rig::read_results_file(path));
    const rig::CampaignResult merged = rig::merge_shards(std::move(shards), a.shards);
    rig::write_results_file(a.out, merged);
    std::fputs(fmt::format("merged {} shards: {} runs, verdict {}; wrote {}\n", a.shards.size(),
                           merged.runs.size(), rig::to_string(merged.verdict), a.out)
                   .c_str(),
               stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hilrig merge: %s\n", e.what());
    return kBadInput;
  }
  return kPassed;
}

} // namespace

void add_merge_command(CLI::App& app) {
  auto args = std::make_shared<MergeArgs>();
  auto* cmd = app.add_subcommand("merge", "merge the results.json of every shard into one");
  cmd->add_option("out", args->out, "the merged results.json to write")->required();
  cmd->add_option("shards", args->shards, "one results.json per shard")->required();
  cmd->callback([args] {
    const int code = run_merge(*args);
    if (code != kPassed) exit_with(code);
  });
}

} // namespace hilrig::cli
