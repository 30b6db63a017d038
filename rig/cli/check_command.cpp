#include "rig/cli/check_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/suite_files.hpp"

namespace hilrig::cli {

int check_campaigns(const std::vector<std::string>& paths, std::ostream& out, std::ostream& err) {
  std::vector<SuiteEntry> entries;
  try {
    entries = collect_campaigns(paths);
  } catch (const std::invalid_argument& e) {
    err << "hilrig check: " << e.what() << '\n';
    return kBadInput;
  }
  int status = kPassed;
  for (const SuiteEntry& e : entries) {
    try {
      const campaign::Campaign c = campaign::load_campaign(e.file);
      const std::size_t checks = c.points.empty() ? 0 : c.points.front().checks.size();
      out << fmt::format("{}: ok ({} run(s), {} check(s) a run)\n", e.file, c.runs.size(), checks);
    } catch (const campaign::CampaignError& error) {
      err << error.what() << '\n'; // as `hilrig run` prints it
      status = kBadInput;
    }
  }
  return status;
}

void add_check_command(CLI::App& app) {
  auto paths = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd =
      app.add_subcommand("check", "validate campaign files (or directories of them) without running");
  cmd->add_option("files", *paths, "campaign files (.toml) and directories (every *.toml under one)")
      ->required();
  cmd->callback([paths] {
    const int status = check_campaigns(*paths, std::cout, std::cerr);
    if (status != kPassed) exit_with(status);
  });
}

} // namespace hilrig::cli
