#pragma once
// "did you mean ...?" for a name that is not one of the valid ones (a campaign key, a check
// parameter, a subcommand, an option): the closest valid names by edit distance.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hilrig {

// Levenshtein distance (insertions, deletions, substitutions each cost 1).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The valid names closest to `name`, nearest first (ties in the order given), and only those
// near enough to be a typo of it: at most 2 edits, and fewer than half of the longer name.
[[nodiscard]] std::vector<std::string> closest_names(std::string_view name,
                                                     const std::vector<std::string>& valid);

// " (did you mean \"x\"?)" or " (did you mean \"x\" or \"y\"?)"; "" when nothing is close.
[[nodiscard]] std::string did_you_mean(std::string_view name, const std::vector<std::string>& valid);

} // namespace hilrig
