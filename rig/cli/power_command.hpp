#pragma once
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "rig/cli/cli_fwd.hpp"

namespace hilrig::cli {

struct PowerOptions {
  std::string file;
  std::filesystem::path out; // "" : write no files
  std::optional<std::uint64_t> seed;
  std::optional<double> max_margin_pct;
  std::vector<std::string> checks;
};

// `hilrig power`: the table on out, progress on err; power.json and power.html into o.out.
// Returns the exit status: 2 bad input (or a hardware campaign), 1 when --max-margin is given
// and a check's margin is over it or it has none, 3 a rig fault, else 0.
int power_campaign(const PowerOptions& o, std::ostream& out, std::ostream& err);

void add_power_command(CLI::App& app);

} // namespace hilrig::cli
