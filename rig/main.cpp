// hilrig: the command-line program. Each subcommand lives in its own library under
// rig/cli/ (one CMake fragment each) and registers itself here; docs/campaigns.md says
// what each does.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iterator>
#include <string>
#include <string_view>

#include "rig/cli/check_command.hpp"
#include "rig/cli/compare_command.hpp"
#include "rig/cli/latency_command.hpp"
#include "rig/cli/list_command.hpp"
#include "rig/cli/merge_command.hpp"
#include "rig/cli/power_command.hpp"
#include "rig/cli/run_command.hpp"
#include "rig/cli/serve_command.hpp"
#include "rig/cli/synth_command.hpp"
#include "rig/cli/trend_command.hpp"
#include "rig/cli/usage_hints.hpp"
#include "rig/results/results_json.hpp"

namespace {

struct Command {
  const char* name;
  void (*add)(CLI::App&);
};

// In the order `hilrig --help` lists them.
constexpr Command kCommands[] = {
    {"synth", hilrig::cli::add_synth_command},     {"run", hilrig::cli::add_run_command},
    {"check", hilrig::cli::add_check_command},     {"list", hilrig::cli::add_list_command},
    {"compare", hilrig::cli::add_compare_command}, {"merge", hilrig::cli::add_merge_command},
    {"serve", hilrig::cli::add_serve_command},     {"latency", hilrig::cli::add_latency_command},
    {"power", hilrig::cli::add_power_command},     {"trend", hilrig::cli::add_trend_command},
};

} // namespace

int main(int argc, char** argv) {
  // A file size limit (`ulimit -f`) would kill the process with SIGXFSZ in the middle of a
  // write, with no message and a *.tmp left behind. Ignored, the write fails with EFBIG instead
  // and every command's own error path runs: the system's reason ("File too large"), no *.tmp,
  // and the exit status the command gives a failed write (docs/campaigns.md, "The output directory").
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"hilrig: a real-time hardware-in-the-loop test rig for AMCI boards"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("hilrig ") + hilrig::rig::tool_version());
  // A command line that starts with a command's name builds only that command's options
  // (building all of them is most of a short run's start-up), and `hilrig --version` alone
  // builds none (CLI11 answers the flag before it asks for a command); any other (--help, a
  // mistyped or missing command) builds them all, for the listing and the hints.
  const std::string_view first = argc > 1 ? std::string_view(argv[1]) : std::string_view();
  const auto* chosen = std::find_if(std::begin(kCommands), std::end(kCommands),
                                    [&](const Command& c) { return first == c.name; });
  if (chosen != std::end(kCommands)) {
    chosen->add(app);
  } else if (!(argc == 2 && first == "--version")) {
    for (const Command& c : kCommands) c.add(app);
  }
  if (const auto problem = hilrig::cli::unknown_word(app, argc, argv)) {
    std::fprintf(stderr, "%s\n", problem->c_str());
    return 2; // bad input, as every usage error
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code(); // a subcommand's own status (rig/cli/exit_status.hpp)
  } catch (const CLI::ParseError& e) {
    // CLI11 exits 0 for --help and 106/109 etc. for usage errors; usage errors are bad input: 2.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hilrig: %s\n", e.what());
    return 3;
  }
  return 0;
}
