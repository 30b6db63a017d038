#include "rig/cli/suite_files.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace hilrig::cli {

namespace fs = std::filesystem;

std::vector<SuiteEntry> collect_campaigns(const std::vector<std::string>& paths) {
  std::vector<SuiteEntry> entries;
  for (const std::string& path : paths) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (fs::is_directory(st)) {
      std::vector<SuiteEntry> found;
      for (const auto& e : fs::recursive_directory_iterator(path)) {
        if (e.path().extension() != ".toml") continue;
        // A link loop, or a link through a directory one may not read, is the suite's to fix:
        // named as bad input, as `hilrig check` names it given alone.
        std::error_code status_ec;
        const fs::file_status s = e.status(status_ec);
        if (status_ec && status_ec != std::errc::no_such_file_or_directory)
          throw std::invalid_argument(fmt::format("{}: {}", e.path().string(), status_ec.message()));
        if (fs::is_directory(s)) continue;
        // A *.toml that is not a campaign file one can read (a dangling link, a FIFO) would
        // drop out of the suite unnoticed: the suite would pass without it.
        if (!fs::is_regular_file(s))
          throw std::invalid_argument(
              fmt::format("{}: {}, not a campaign file", e.path().string(),
                          fs::exists(s) ? "not a regular file" : "a link to nothing"));
        const fs::path rel = e.path().lexically_relative(path);
        found.push_back({e.path().string(), fs::path(rel).replace_extension().generic_string()});
      }
      if (found.empty())
        throw std::invalid_argument(fmt::format("{}: a directory without any *.toml campaign", path));
      std::sort(found.begin(), found.end(),
                [](const SuiteEntry& a, const SuiteEntry& b) { return a.subdir < b.subdir; });
      entries.insert(entries.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(st)) {
      if (fs::path(path).extension() != ".toml")
        throw std::invalid_argument(fmt::format("{}: a campaign file (*.toml) or a directory of them", path));
      entries.push_back({path, fs::path(path).stem().string()});
    } else if (fs::exists(st)) {
      throw std::invalid_argument(
          fmt::format("{}: not a regular file (a campaign file (*.toml) or a directory of them)", path));
    } else {
      // Not there, or not to be looked at (a link loop, no permission): the campaign reader
      // refuses it as any file it cannot open, "x.toml: file: a readable campaign file (cannot
      // open it: ...)" (docs/campaigns.md), beside the suite's other files' problems.
      entries.push_back({path, fs::path(path).stem().string()});
    }
  }
  std::map<std::string, std::string> by_subdir;
  for (const SuiteEntry& e : entries) {
    const auto [it, fresh] = by_subdir.emplace(e.subdir, e.file);
    if (!fresh)
      throw std::invalid_argument(fmt::format("{} and {} would both write to {}/ (give one of them, or their "
                                              "directory)",
                                              it->second, e.file, e.subdir));
  }
  return entries;
}

} // namespace hilrig::cli
