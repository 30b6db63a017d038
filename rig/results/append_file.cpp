#include "rig/results/append_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace hilrig::rig {

AppendFile::AppendFile(const std::filesystem::path& path, Sync sync) : path_(path), sync_(sync) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view block) {
  // One write() of the whole block: a short write only happens at a size limit or a full
  // disk, and then the partial block is cut off again so the file ends on a whole block.
  ssize_t n = -1;
  do n = ::write(fd_, block.data(), block.size());
  while (n < 0 && errno == EINTR);
  int err = 0;
  if (n < 0)
    err = errno;
  else if (static_cast<std::size_t>(n) != block.size())
    err = EFBIG;
  else if (sync_ == Sync::EachBlock && ::fdatasync(fd_) != 0)
    err = errno;
  if (err != 0) {
    if (::ftruncate(fd_, size_) != 0) { /* a reader of the file ignores a torn last line */
    }
    throw std::runtime_error(fmt::format("cannot write {}: {}", path_.string(), std::strerror(err)));
  }
  size_ += static_cast<off_t>(block.size());
}

} // namespace hilrig::rig
