#pragma once
#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {
// `hilrig compare BASE.json NEW.json [--threshold NAME=VALUE[%] ...] [--default-rel 0.05] [--all]`:
// per-measurement drift against thresholds; exit 1 on a regression (a drift beyond its
// threshold, a measurement that disappeared or newly fails, a worse verdict), 2 on bad input.
void add_compare_command(CLI::App& app);
} // namespace hilrig::cli
