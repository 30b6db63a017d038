#pragma once
// `hilrig list`: the devices this build can simulate (pins, parameters, variants), the
// check kinds (parameters), and the stimulus kinds and signal faults, from the registries.

#include <iosfwd>

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

void add_list_command(CLI::App& app);

// Writes the listing (what the command prints).
void write_listing(std::ostream& out);

} // namespace hilrig::cli
