#include "tests/signals/run_synth.hpp"

#include <CLI/CLI.hpp>

#include "rig/cli/synth_command.hpp"

namespace hilrig::test {

void synth(std::vector<std::string> args) {
  CLI::App app{"hilrig"};
  app.require_subcommand(1);
  cli::add_synth_command(app);
  args.insert(args.begin(), {"hilrig", "synth"});
  std::vector<const char*> argv;
  argv.reserve(args.size());
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

} // namespace hilrig::test
