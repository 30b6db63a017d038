#pragma once
// `hilrig check FILE|DIR...`: reads every campaign as `hilrig run` would (the same checks, the
// same messages) and runs nothing: exit 0 when all are good, 2 when any is not.

#include <iosfwd>
#include <string>
#include <vector>

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

void add_check_command(CLI::App& app);

// Each good file as "FILE: ok (N runs, M checks)" on out; each problem on err. Exit status.
[[nodiscard]] int check_campaigns(const std::vector<std::string>& paths, std::ostream& out,
                                  std::ostream& err);

} // namespace hilrig::cli
