#include "rig/cli/output_dir.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

namespace hilrig::cli {

OutputDirectory::OutputDirectory(const std::filesystem::path& dir, Holds holds) {
  // --out naming a file (or a path through one) is the user's to change: bad input, not a rig
  // fault. Other failures (permissions, a full disk) keep the errno text.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec == std::errc::not_a_directory || ec == std::errc::file_exists ||
      (!ec && !std::filesystem::is_directory(dir)))
    throw ForeignOutput(
        fmt::format("--out {}: not a directory (it or a path above it is a file): give an empty "
                    "or new directory",
                    dir.string()));
  if (ec) throw std::filesystem::filesystem_error("cannot create --out", dir, ec);
  if (!lock_.take(dir, DirectoryLock::Missing::Create))
    throw OutputBusy(fmt::format("--out {}: another hilrig run is writing this directory (it holds {})",
                                 dir.string(), lock_.path().string()));
  std::vector<std::filesystem::path> evidence;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (holds == Holds::Suite && entry.is_directory()) continue; // a campaign's own, cleared when it runs
    if (!entry.is_regular_file() || !is_run_evidence(name))
      throw ForeignOutput(fmt::format("--out {}: holds {}, which hilrig run does not write: give an empty or "
                                      "new directory, or one an earlier hilrig run wrote",
                                      dir.string(), name));
    if (name != kDirectoryLockName) evidence.push_back(entry.path());
  }
  for (const auto& path : evidence) std::filesystem::remove(path);
}

} // namespace hilrig::cli
