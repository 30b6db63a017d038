#include "rig/cli/trend_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rig/cli/exit_status.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/trend_html.hpp"

namespace hilrig::cli {
namespace {

struct TrendArgs {
  std::vector<std::string> files;
  std::string out;
};

int run_trend(const TrendArgs& a) {
  std::vector<rig::CampaignResult> results;
  std::vector<rig::Night> nights;
  try {
    results.reserve(a.files.size());
    for (const std::string& f : a.files) results.push_back(rig::read_results_file(f));
    for (std::size_t i = 0; i < results.size(); ++i)
      // A night is named by when it ran, when its results say so; else by its file.
      nights.push_back(rig::Night{&results[i], results[i].started_at.value_or(a.files[i]), a.files[i]});
    rig::write_file_atomically(a.out, rig::to_trend_html(nights));
  } catch (const std::exception& e) {
    std::fputs(fmt::format("hilrig trend: {}\n", e.what()).c_str(), stderr);
    return kBadInput;
  }
  std::fputs(
      fmt::format("trend: {} night(s) of {}: {}\n", nights.size(), results.front().campaign, a.out).c_str(),
      stdout);
  return kPassed;
}

} // namespace

void add_trend_command(CLI::App& app) {
  auto args = std::make_shared<TrendArgs>();
  auto* cmd = app.add_subcommand(
      "trend", "one HTML page of each measurement against its limits over the nights' results.json files");
  cmd->add_option("results", args->files, "results.json files of one campaign, oldest first")->required();
  cmd->add_option("--out", args->out, "the HTML file to write")->required();
  cmd->callback([args] {
    const int code = run_trend(*args);
    if (code != kPassed) exit_with(code);
  });
}

} // namespace hilrig::cli
