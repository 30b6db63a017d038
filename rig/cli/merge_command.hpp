#pragma once
#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {
// `hilrig merge OUT.json SHARD.json...`: merges the results of every shard of a campaign into
// one results file equal to the unsharded run; exit 2 when shards are missing or mismatched.
void add_merge_command(CLI::App& app);
} // namespace hilrig::cli
