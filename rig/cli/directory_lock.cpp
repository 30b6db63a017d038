#include "rig/cli/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace hilrig::cli {

bool DirectoryLock::take(const std::filesystem::path& dir, Missing missing) {
  if (fd_ >= 0) throw std::logic_error("DirectoryLock::take: already held");
  path_ = dir / kDirectoryLockName;
  const int flags = missing == Missing::Create ? O_RDWR | O_CREAT | O_CLOEXEC : O_RDONLY | O_CLOEXEC;
  fd_ = ::open(path_.c_str(), flags, 0644);
  if (fd_ < 0) {
    if (missing == Missing::HoldNothing && errno == ENOENT) return true;
    throw std::runtime_error(fmt::format("cannot open {}: {}", path_.string(), std::strerror(errno)));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return true;
  const int err = errno;
  ::close(fd_);
  fd_ = -1;
  if (err == EWOULDBLOCK) return false;
  throw std::runtime_error(fmt::format("cannot lock {}: {}", path_.string(), std::strerror(err)));
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);
}

} // namespace hilrig::cli
