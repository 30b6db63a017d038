#include "rig/cli/power_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/check_selection.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/seed_option.hpp"
#include "rig/power/power.hpp"
#include "rig/power/power_report.hpp"
#include "rig/results/results_json.hpp"

namespace hilrig::cli {

int power_campaign(const PowerOptions& o, std::ostream& out, std::ostream& err) {
  campaign::Campaign c;
  try {
    c = campaign::load_campaign(o.file);
  } catch (const campaign::CampaignError& e) {
    err << e.what() << '\n';
    return kBadInput;
  }
  for (const campaign::Scenario& s : c.points)
    if (s.dut.backend != "virtual") {
      err << fmt::format("hilrig power: {}: [dut] backend \"{}\": detection power is measured on the virtual "
                         "board only\n",
                         o.file, s.dut.backend);
      return kBadInput;
    }
  if (o.max_margin_pct && !(*o.max_margin_pct >= 0.0)) {
    err << "hilrig power: --max-margin: expected a percentage >= 0\n";
    return kBadInput;
  }
  const std::vector<std::string> names = campaign::check_names(c);
  for (const std::string& n : o.checks)
    if (std::find(names.begin(), names.end(), n) == names.end()) {
      err << fmt::format("hilrig power: --check {}: {} has no check of this name{}\n", n, o.file,
                         did_you_mean(n, names));
      return kBadInput;
    }
  // The output directory before the bisection, not after it: an --out that is a file (or
  // under one) is bad input, found before minutes of probes.
  if (!o.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.out, ec);
    if (ec || !std::filesystem::is_directory(o.out)) {
      err << fmt::format("hilrig power: --out {}: not a directory that can be made ({})\n", o.out.string(),
                         ec ? ec.message() : "a file is in the way");
      return kBadInput;
    }
  }
  power::PowerResult result;
  try {
    power::PowerOptions options;
    options.seed = o.seed;
    options.checks = o.checks;
    options.progress = [&err](const std::string& line) { err << line << '\n' << std::flush; };
    result = power::measure_power(c, options);
    if (!o.out.empty()) {
      rig::write_file_atomically(o.out / "power.json", power::to_power_json(result));
      rig::write_file_atomically(o.out / "power.html", power::to_power_html(result));
    }
  } catch (const std::exception& e) {
    err << "hilrig power: rig fault: " << e.what() << '\n';
    return kRigFault;
  }
  out << power::to_power_text(result);
  if (!o.max_margin_pct) return kPassed;
  int status = kPassed;
  for (const power::PowerRow& r : result.rows)
    if (power::over_margin(r, *o.max_margin_pct)) {
      err << fmt::format("hilrig power: {}: {}\n", r.check,
                         r.margin_pct ? fmt::format("margin {:.4f} % is over --max-margin {} %",
                                                    *r.margin_pct, *o.max_margin_pct)
                                      : "no margin: " + (r.reason.empty() ? r.detail : r.reason));
      status = kCheckFailed;
    }
  return status;
}

void add_power_command(CLI::App& app) {
  auto o = std::make_shared<PowerOptions>();
  auto max_margin = std::make_shared<double>(-1.0);
  CLI::App* cmd = app.add_subcommand(
      "power", "detection power: bisect each check's knob on the virtual board to where the check fails");
  cmd->add_option("campaign", o->file, "campaign file (.toml)")->required();
  cmd->add_option("--out", o->out, "write power.json and power.html into this directory");
  add_seed_option(*cmd, o->seed, "base seed (default: the campaign's)");
  cmd->add_option("--max-margin", *max_margin,
                  "exit 1 when a check's margin beyond its limit is over PCT %, or it has none");
  cmd->add_option("--check", o->checks, "only this check (repeatable)")->allow_extra_args(false);
  cmd->callback([o, max_margin, cmd] {
    if (cmd->count("--max-margin") > 0) o->max_margin_pct = *max_margin;
    const int status = power_campaign(*o, std::cout, std::cerr);
    if (status != kPassed) exit_with(status);
  });
}

} // namespace hilrig::cli
