#include "rig/cli/usage_hints.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"

namespace hilrig::cli {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A value, not an option: "-" (stdin), a negative number or duration ("-3", "-0.5", "-1ms",
// "-5us"): no option's name starts with a digit.
bool is_value(std::string_view word) {
  if (word.size() < 2 || word[0] != '-') return true;
  return (word[1] >= '0' && word[1] <= '9') || word[1] == '.';
}

std::vector<std::string> option_names(const CLI::App& cmd) {
  std::vector<std::string> names{"--help", "-h"};
  for (const CLI::Option* o : cmd.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

} // namespace

std::optional<std::string> unknown_word(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2) return std::nullopt;
  const std::string first = argv[1];
  if (first.starts_with("-")) return std::nullopt; // --help, --version: CLI11's
  // The command the words name: "synth quadrature ..." is the quadrature command of synth, and
  // its options are quadrature's (a command that requires one of its own commands gets the
  // same hint for a mistyped one as the top level does).
  const CLI::App* cmd = &app;
  std::string path;
  int i = 1;
  for (; i < argc; ++i) {
    const std::vector<const CLI::App*> subs = cmd->get_subcommands([](const CLI::App*) { return true; });
    const std::string_view word = argv[i];
    if (subs.empty() || word.starts_with("-")) break;
    const auto named =
        std::find_if(subs.begin(), subs.end(), [&](const CLI::App* s) { return s->get_name() == word; });
    if (named == subs.end()) {
      if (cmd->get_require_subcommand_min() == 0) break; // a positional of this command
      std::vector<std::string> commands;
      for (const CLI::App* s : subs) commands.push_back(s->get_name());
      const std::string here = path.empty() ? "hilrig" : "hilrig " + path;
      return fmt::format("{}: {}: no such command{}; commands: {} ({} --help)", here, word,
                         did_you_mean(std::string(word), commands), joined(commands), here);
    }
    cmd = *named;
    path += (path.empty() ? "" : " ") + std::string(word);
  }
  const std::vector<std::string> options = option_names(*cmd);
  for (; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--") break; // what follows is positional
    if (is_value(word)) continue;
    const std::string name(word.substr(0, word.find('=')));
    // -j4: a short option with its value attached.
    const bool known = std::find(options.begin(), options.end(), name) != options.end() ||
                       (!name.starts_with("--") &&
                        std::find(options.begin(), options.end(), name.substr(0, 2)) != options.end());
    if (!known)
      return fmt::format("hilrig {}: {}: no such option{} (hilrig {} --help lists them)", path, name,
                         did_you_mean(name, options), path);
    // The word after an option that needs a value is that value, as CLI11 takes it whatever it
    // looks like: "--rpm -inf" is --rpm's bad value, judged by --rpm, not an option "-inf".
    const bool attached =
        word.find('=') != std::string_view::npos || (!name.starts_with("--") && name.size() > 2);
    const CLI::Option* option = attached ? nullptr : cmd->get_option_no_throw(name);
    if (option != nullptr && option->get_items_expected_min() > 0) ++i;
  }
  return std::nullopt;
}

} // namespace hilrig::cli
