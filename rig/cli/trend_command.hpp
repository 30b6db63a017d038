#pragma once
// `hilrig trend RESULTS.json... --out trend.html`: the nights' results of one campaign (oldest
// first) as one self-contained HTML page, each measurement's value against its limits over the
// nights. Exit 2 when a file cannot be read or the files are not one campaign on one device.

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

void add_trend_command(CLI::App& app);

} // namespace hilrig::cli
