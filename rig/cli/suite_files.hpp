#pragma once
// The campaigns of `hilrig run A.toml B.toml DIR/ ...` and where each one's outputs go.
// A directory is a suite: every *.toml under it (recursively), sorted by path, so the same
// tree always yields the same order and the same output directories.

#include <string>
#include <vector>

namespace hilrig::cli {

struct SuiteEntry {
  std::string file;   // the campaign file (a path as given, or under a directory given)
  std::string subdir; // its outputs: OUT/<subdir>/ (a directory's file: its path under the
                      // directory without ".toml"; a file given by name: its stem)
};

// Throws std::invalid_argument naming the path: a file that is not .toml, one that is not a
// regular file, a directory without any, or two campaigns whose outputs would share a
// directory. A path that is not there (or cannot be looked at) is entered as a campaign file:
// reading it refuses it as the campaign reader refuses any file it cannot open.
[[nodiscard]] std::vector<SuiteEntry> collect_campaigns(const std::vector<std::string>& paths);

} // namespace hilrig::cli
