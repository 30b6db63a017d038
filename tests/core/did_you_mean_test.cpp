// "did you mean": Levenshtein distance and the closest valid names, as the campaign reader,
// the check registry and the command line use them.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/did_you_mean.hpp"

namespace hilrig {
namespace {

TEST(DidYouMean, EditDistanceCountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0U);
  EXPECT_EQ(edit_distance("run", "run"), 0U);
  EXPECT_EQ(edit_distance("rn", "run"), 1U);         // one insertion
  EXPECT_EQ(edit_distance("runn", "run"), 1U);       // one deletion
  EXPECT_EQ(edit_distance("ron", "run"), 1U);        // one substitution
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3U); // the textbook pair
  EXPECT_EQ(edit_distance("", "abc"), 3U);
  // Symmetric, and within the triangle inequality, over a few words.
  const std::vector<std::string> w{"motion", "motoin", "moton", "notion", "", "m"};
  for (const auto& a : w)
    for (const auto& b : w) {
      EXPECT_EQ(edit_distance(a, b), edit_distance(b, a)) << a << " " << b;
      for (const auto& c : w) EXPECT_LE(edit_distance(a, c), edit_distance(a, b) + edit_distance(b, c));
    }
}

TEST(DidYouMean, SuggestsOnlyNamesATypoAway) {
  const std::vector<std::string> commands{"synth",   "run",   "check", "list",
                                          "compare", "merge", "serve", "latency"};
  EXPECT_EQ(did_you_mean("rn", commands), " (did you mean \"run\"?)");
  EXPECT_EQ(did_you_mean("chekc", commands), " (did you mean \"check\"?)");
  EXPECT_EQ(did_you_mean("serv", commands), " (did you mean \"serve\"?)");
  EXPECT_EQ(did_you_mean("xyzzy", commands), "");
  EXPECT_EQ(did_you_mean("run", commands), ""); // a valid name is no typo
  // Short names need a closer match: "ab" is 2 edits from "run" and from "list", too far.
  EXPECT_EQ(did_you_mean("ab", commands), "");
  // Two equally close names: both, in the order given.
  EXPECT_EQ(did_you_mean("--ou", {"--out", "--only", "--our"}), " (did you mean \"--out\" or \"--our\"?)");
  EXPECT_EQ(closest_names("limt_us", {"limit_us", "min_count", "limit_ns"}),
            (std::vector<std::string>{"limit_us", "limit_ns"}));
}

} // namespace
} // namespace hilrig
