// hilrig: the command-line program. Each subcommand lives in its own library under
// rig/cli/ and registers itself here; see docs/campaigns.md for what each does.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#ifdef HILRIG_HAVE_SYNTH_COMMAND
#include "rig/cli/synth_command.hpp"
#endif
#ifdef HILRIG_HAVE_RUN_COMMAND
#include "rig/cli/run_command.hpp"
#endif
#ifdef HILRIG_HAVE_LIST_COMMAND
#include "rig/cli/list_command.hpp"
#endif
#ifdef HILRIG_HAVE_COMPARE_COMMAND
#include "rig/cli/compare_command.hpp"
#endif
#ifdef HILRIG_HAVE_MERGE_COMMAND
#include "rig/cli/merge_command.hpp"
#endif
#ifdef HILRIG_HAVE_SERVE_COMMAND
#include "rig/cli/serve_command.hpp"
#endif
#ifdef HILRIG_HAVE_LATENCY_COMMAND
#include "rig/cli/latency_command.hpp"
#endif

int main(int argc, char** argv) {
  CLI::App app{"hilrig: a real-time hardware-in-the-loop test rig for AMCI boards"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hilrig 0.1.0");
#ifdef HILRIG_HAVE_SYNTH_COMMAND
  hilrig::cli::add_synth_command(app);
#endif
#ifdef HILRIG_HAVE_RUN_COMMAND
  hilrig::cli::add_run_command(app);
#endif
#ifdef HILRIG_HAVE_LIST_COMMAND
  hilrig::cli::add_list_command(app);
#endif
#ifdef HILRIG_HAVE_COMPARE_COMMAND
  hilrig::cli::add_compare_command(app);
#endif
#ifdef HILRIG_HAVE_MERGE_COMMAND
  hilrig::cli::add_merge_command(app);
#endif
#ifdef HILRIG_HAVE_SERVE_COMMAND
  hilrig::cli::add_serve_command(app);
#endif
#ifdef HILRIG_HAVE_LATENCY_COMMAND
  hilrig::cli::add_latency_command(app);
#endif
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
