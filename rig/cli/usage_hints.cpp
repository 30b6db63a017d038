#include "rig/cli/usage_hints.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
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

// A value, not an option: "-" (stdin), a negative number ("-3", "-0.5").
bool is_value(std::string_view word) {
  if (word.size() < 2 || word[0] != '-') return true;
  double v = 0.0;
  const auto r = std::from_chars(word.data() + 1, word.data() + word.size(), v);
  return r.ec == std::errc{} && r.ptr == word.data() + word.size();
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
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(sub->get_name());
  if (argc < 2) return std::nullopt;
  const std::string first = argv[1];
  if (first.starts_with("-")) return std::nullopt; // --help, --version: CLI11's
  const CLI::App* cmd = nullptr;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == first) cmd = sub;
  if (cmd == nullptr)
    return fmt::format("hilrig: {}: no such command{}; commands: {} (hilrig --help)", first,
                       did_you_mean(first, commands), joined(commands));
  const std::vector<std::string> options = option_names(*cmd);
  for (int i = 2; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--") break; // what follows is positional
    if (is_value(word)) continue;
    const std::string name(word.substr(0, word.find('=')));
    // -j4: a short option with its value attached.
    const bool known = std::find(options.begin(), options.end(), name) != options.end() ||
                       (!name.starts_with("--") &&
                        std::find(options.begin(), options.end(), name.substr(0, 2)) != options.end());
    if (!known)
      return fmt::format("hilrig {}: {}: no such option{} (hilrig {} --help lists them)", first, name,
                         did_you_mean(name, options), first);
  }
  return std::nullopt;
}

} // namespace hilrig::cli
