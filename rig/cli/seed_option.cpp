#include "rig/cli/seed_option.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <limits>

#include <fmt/format.h>

namespace hilrig::cli {

std::optional<std::uint64_t> parse_seed(std::string_view text) {
  // from_chars takes no sign, no space and no base prefix: only the digits of a decimal number;
  // it reports a number past 2^64-1 as out of range rather than wrapping it.
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string seed_range_message(std::string_view text) {
  return fmt::format("'{}' is not a seed: a seed is a decimal integer 0..{} (unsigned 64-bit)", text,
                     std::numeric_limits<std::uint64_t>::max());
}

CLI::Option* add_seed_option(CLI::App& cmd, std::optional<std::uint64_t>& seed, const std::string& what) {
  return cmd
      .add_option_function<std::string>(
          "--seed",
          [&seed](const std::string& text) {
            const std::optional<std::uint64_t> v = parse_seed(text);
            if (!v) throw CLI::ValidationError("--seed", seed_range_message(text));
            seed = *v;
          },
          what)
      ->type_name("SEED");
}

} // namespace hilrig::cli
