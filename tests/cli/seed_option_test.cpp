// --seed: one parser for run and power (rig/cli/seed_option.hpp). A seed is an unsigned 64-bit
// integer: every value 0..2^64-1 is taken, and nothing else (no sign, no wrap, no clamp).
#include "rig/cli/seed_option.hpp"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hilrig::cli {
namespace {

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max(); // 18446744073709551615

// The top of the range, a neighbourhood on each side of 2^63 (where a signed parser stops) and
// of 2^64 (where an unsigned one overflows).
TEST(SeedOption, TakesEverySeedUpTo2To64Minus1) {
  EXPECT_EQ(parse_seed("0"), 0U);
  EXPECT_EQ(parse_seed("1"), 1U);
  for (std::uint64_t d = 0; d < 4; ++d) {
    const std::uint64_t below = (std::uint64_t{1} << 63) - 1 - d;
    const std::uint64_t above = (std::uint64_t{1} << 63) + d;
    EXPECT_EQ(parse_seed(std::to_string(below)), below);
    EXPECT_EQ(parse_seed(std::to_string(above)), above);
    EXPECT_EQ(parse_seed(std::to_string(kMax - d)), kMax - d);
  }
  EXPECT_EQ(parse_seed("18446744073709551615"), kMax);
  EXPECT_EQ(parse_seed("007"), 7U); // leading zeros are still decimal
}

TEST(SeedOption, RefusesNegativesOverflowAndOtherSpellings) {
  for (const char* bad : {"18446744073709551616", "18446744073709551617", "99999999999999999999999", "-1",
                          "-0", "-9223372036854775808", "+5", "", " 5", "5 ", "0x10", "1e3", "1.0", "seed"})
    EXPECT_EQ(parse_seed(bad), std::nullopt) << "'" << bad << "'";
}

TEST(SeedOption, TheMessageNamesTheValidRange) {
  EXPECT_EQ(seed_range_message("-1"),
            "'-1' is not a seed: a seed is a decimal integer 0..18446744073709551615 (unsigned 64-bit)");
}

// Both commands add it the same way: the option sets the seed, or fails the parse (exit 2 in
// hilrig's main) with the message, leaving the seed unset.
TEST(SeedOption, TheOptionSetsTheSeedOrFailsTheParse) {
  const auto parse = [](const std::string& value) {
    CLI::App app;
    std::optional<std::uint64_t> seed;
    add_seed_option(app, seed, "base seed");
    std::vector<std::string> args{value, "--seed"}; // CLI11 reads the vector back to front
    try {
      app.parse(args);
    } catch (const CLI::ValidationError& e) {
      EXPECT_NE(std::string(e.what()).find("0..18446744073709551615"), std::string::npos) << e.what();
      EXPECT_FALSE(seed);
      return std::optional<std::uint64_t>{};
    }
    return seed;
  };
  EXPECT_EQ(parse("18446744073709551615"), kMax);
  EXPECT_EQ(parse("9223372036854775808"), std::uint64_t{1} << 63);
  EXPECT_EQ(parse("18446744073709551616"), std::nullopt);
  EXPECT_EQ(parse("-1"), std::nullopt);
}

} // namespace
} // namespace hilrig::cli
