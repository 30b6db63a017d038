#include "core/did_you_mean.hpp"

#include <algorithm>
#include <numeric>

namespace hilrig {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0U : 1U)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& valid) {
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const std::string& v : valid) {
    const std::size_t d = edit_distance(name, v);
    const std::size_t longer = std::max(name.size(), v.size());
    if (d > 0 && d <= 2 && 2 * d < longer) near.emplace_back(d, v);
  }
  std::stable_sort(near.begin(), near.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (auto& [d, v] : near)
    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(std::move(v));
  return out;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& valid) {
  const std::vector<std::string> near = closest_names(name, valid);
  if (near.empty()) return {};
  if (near.size() == 1) return " (did you mean \"" + near[0] + "\"?)";
  return " (did you mean \"" + near[0] + "\" or \"" + near[1] + "\"?)";
}

} // namespace hilrig
