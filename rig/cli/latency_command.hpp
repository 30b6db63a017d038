#pragma once
#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {
// `hilrig latency`: the rig's own RT loop measured on this machine, printed like cyclictest.
void add_latency_command(CLI::App& app);
} // namespace hilrig::cli
