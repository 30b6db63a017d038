#pragma once
// The lock that says a hilrig run is writing a directory: flock() on DIR/.hilrig.lock, held
// until the holder is destroyed or its process ends, however it ends (the kernel drops it).
// `hilrig run --out DIR` takes it for the whole run; `hilrig merge` takes it to write into a
// run's directory, so neither overwrites the other.

#include <filesystem>

namespace hilrig::cli {

inline constexpr const char* kDirectoryLockName = ".hilrig.lock";

class DirectoryLock {
public:
  // What taking the lock does when DIR/.hilrig.lock is absent: create it (a run), or hold
  // nothing (a merge: no run ever wrote there, so none can be writing).
  enum class Missing { Create, HoldNothing };

  // Takes DIR's lock without waiting. Returns false when another process holds it; throws
  // std::runtime_error with the errno text when the file cannot be opened or locked.
  [[nodiscard]] bool take(const std::filesystem::path& dir, Missing missing);
  // The lock file's path, once take() ran.
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  DirectoryLock() = default;
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

private:
  std::filesystem::path path_;
  int fd_ = -1;
};

} // namespace hilrig::cli
