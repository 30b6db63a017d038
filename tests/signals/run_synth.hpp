#pragma once
// Runs `hilrig synth ARGS...` in-process, as the command line would, so a test can read the
// VCD it writes.

#include <string>
#include <vector>

#include "rig/cli/synth_command.hpp"

namespace hilrig::test {

inline void synth(std::vector<std::string> args) {
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
