#pragma once
// An output file that grows by whole blocks (a run's record, a run's CAN frames): each block is
// one write() on an O_APPEND descriptor, so a crash of hilrig leaves whole blocks only; with
// Sync::EachBlock it is followed by fdatasync(), so a power loss loses at most the block in
// flight. A write that fails (ENOSPC, EFBIG, EIO) truncates the file back to its last whole
// block and throws std::runtime_error naming the file and the errno text: what was written
// before is kept, nothing half-written stays behind.

#include <filesystem>
#include <string_view>

#include <sys/types.h>

namespace hilrig::rig {

class AppendFile {
public:
  // EachBlock: the record a power loss must not lose (the run log). None: a file the run log's
  // results do not depend on (can.log: a rerun gives the same bytes), where an fdatasync per
  // run was a tenth of a short campaign's CPU (docs/PERFORMANCE.md, "Fixed cost of a run").
  enum class Sync { EachBlock, None };
  // Creates (truncates) path. Throws std::runtime_error with the errno text.
  explicit AppendFile(const std::filesystem::path& path, Sync sync = Sync::EachBlock);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  void append(std::string_view block);
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
  Sync sync_;
  int fd_ = -1;
  off_t size_ = 0; // bytes of whole blocks written
};

} // namespace hilrig::rig
