#include "rig/cli/compare_command.hpp"

#include <algorithm>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/cli/exit_status.hpp"
#include "rig/cli/number_checks.hpp"
#include "rig/results/compare.hpp"
#include "rig/results/results_json.hpp"

namespace hilrig::cli {
namespace {

struct CompareArgs {
  std::string base;
  std::string now;
  std::vector<std::string> thresholds;
  double default_rel = 0.05;
  bool all = false;
};

int run_compare(const CompareArgs& a) {
  rig::CompareOptions options;
  options.default_rel = a.default_rel;
  rig::CampaignResult base;
  rig::CampaignResult now;
  try {
    for (const auto& t : a.thresholds) options.thresholds.push_back(rig::parse_threshold(t));
    base = rig::read_results_file(a.base);
    now = rig::read_results_file(a.now);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hilrig compare: %s\n", e.what());
    return kBadInput;
  }
  // A baseline is the same campaign on the same device: anything else would compare strangers
  // measurement by measurement and call the difference a drift.
  if (base.campaign != now.campaign || base.device != now.device) {
    std::fputs(
        fmt::format("hilrig compare: {} is campaign \"{}\" on {}, {} is campaign \"{}\" on {}: a baseline "
                    "must be the same campaign on the same device\n",
                    a.base, base.campaign, base.device, a.now, now.campaign, now.device)
            .c_str(),
        stderr);
    return kBadInput;
  }
  const rig::Comparison c = rig::compare_results(base, now, options);
  // A threshold is a pattern, and one list may serve several campaigns, so one that names no
  // measurement here is not an error; but a misspelt one silently judges nothing: say so.
  for (const rig::Threshold& t : options.thresholds)
    if (std::none_of(c.rows.begin(), c.rows.end(),
                     [&](const rig::DriftRow& row) { return rig::threshold_matches(t, row.measurement); }))
      std::fputs(fmt::format("hilrig compare: warning: --threshold {}: no measurement of {} or {} is named "
                             "\"{}\" or ends in \".{}\"; it applies to none\n",
                             t.name, a.base, a.now, t.name, t.name)
                     .c_str(),
                 stderr);
  std::fputs(rig::format_comparison(c, a.all).c_str(), stdout);
  return c.regression() ? kCheckFailed : kPassed;
}

} // namespace

void add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  auto* cmd = app.add_subcommand("compare", "compare a results.json with a baseline; exit 1 on a regression");
  cmd->add_option("base", args->base, "the baseline results.json")->required();
  cmd->add_option("new", args->now, "the new results.json")->required();
  cmd->add_option("--threshold", args->thresholds,
                  "NAME=VALUE (absolute, in the measurement's unit) or NAME=VALUE% (relative); NAME is a "
                  "measurement name or its dotted suffix, e.g. p99=2 or ls1.max=5%");
  cmd->add_option("--default-rel", args->default_rel,
                  "relative threshold for unnamed measurements (0.05 = 5%)")
      ->check(non_negative_number());
  cmd->add_flag("--all", args->all, "list every measurement, not only drifts, regressions and improvements");
  cmd->callback([args] {
    const int code = run_compare(*args);
    if (code != kPassed) exit_with(code);
  });
}

} // namespace hilrig::cli
