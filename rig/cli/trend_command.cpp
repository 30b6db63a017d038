#include "rig/cli/trend_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rig/cli/exit_status.hpp"
#include "rig/cli/run_evidence.hpp"
#include "rig/cli/same_file.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/trend_html.hpp"

namespace hilrig::cli {
namespace {

struct TrendArgs {
  std::vector<std::string> files;
  std::string out;
};

// An --out that is one of the nights' results.json (by any spelling), or a file `hilrig run`
// wrote beside one (its trace.vcd, junit.xml, ...), would replace that night's evidence with the
// page, and one file given twice would be drawn as two nights: all refused before anything is
// read or written.
void refuse_overwriting_or_repeating_an_input(const TrendArgs& a) {
  const std::filesystem::path out(a.out);
  const auto directory = [](const std::filesystem::path& p) {
    return p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  };
  for (std::size_t i = 0; i < a.files.size(); ++i) {
    if (same_file(a.out, a.files[i]))
      throw std::invalid_argument(fmt::format("--out {} is also an input ({}): the trend would overwrite it; "
                                              "write the page elsewhere (e.g. trend.html)",
                                              a.out, a.files[i]));
    if (is_run_evidence(out.filename().string()) && same_file(directory(out), directory(a.files[i])))
      throw std::invalid_argument(
          fmt::format("--out {} is the run's own file beside the input {}: the trend "
                      "would overwrite it; write the page elsewhere (e.g. trend.html)",
                      a.out, a.files[i]));
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(a.files[j], a.files[i]))
        throw std::invalid_argument(fmt::format("{} and {} are one file given twice: give each night's "
                                                "results.json once",
                                                a.files[j], a.files[i]));
  }
}

int run_trend(const TrendArgs& a) {
  std::vector<rig::CampaignResult> results;
  std::vector<rig::Night> nights;
  try {
    refuse_overwriting_or_repeating_an_input(a);
    results.reserve(a.files.size());
    for (const std::string& f : a.files) results.push_back(rig::read_results_file(f));
    for (std::size_t i = 0; i < results.size(); ++i)
      // A night is named by when it ran, when its results say so; else by its file.
      nights.push_back(rig::Night{&results[i], results[i].started_at.value_or(a.files[i]), a.files[i]});
    const std::string page = rig::to_trend_html(nights);
    try {
      rig::write_file_atomically(a.out, page);
    } catch (const std::exception& e) {
      throw WriteFailed(e.what());
    }
  } catch (const WriteFailed& e) {
    std::fputs(fmt::format("hilrig trend: {}\n", e.what()).c_str(), stderr);
    return kRigFault; // as `hilrig run` exits when it cannot write
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
