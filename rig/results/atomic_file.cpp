#include "rig/results/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <memory>
#include <stdexcept>
#include <streambuf>
#include <unistd.h>

namespace hilrig::rig {
namespace {

// An ostream's buffer over a file descriptor. A failed write() ends the stream (badbit) and
// keeps its errno for the caller to report; nothing is thrown through the ostream. The buffer
// is taken at the first small write: text written in one block goes straight to write().
class FdBuffer : public std::streambuf {
public:
  explicit FdBuffer(int fd) : fd_(fd) {}
  [[nodiscard]] int error() const { return error_; }

protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!buffer_) take_buffer();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n < epptr() - pptr()) {
      std::memcpy(pptr(), s, static_cast<std::size_t>(n));
      pbump(static_cast<int>(n));
      return n;
    }
    if (!buffer_ && n < static_cast<std::streamsize>(kSize)) {
      take_buffer();
      return xsputn(s, n);
    }
    // Larger than the room left: out with what is held, then the block itself, unbuffered.
    if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
    return n;
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  static constexpr std::size_t kSize = std::size_t{1} << 20U;
  void take_buffer() {
    buffer_ = std::make_unique_for_overwrite<char[]>(kSize);
    setp(buffer_.get(), buffer_.get() + kSize);
  }
  bool drain() {
    const bool ok = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(pbase(), epptr());
    return ok;
  }
  bool write_all(const char* data, std::size_t size) {
    if (error_ != 0) return false;
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::write(fd_, data + done, size - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return false;
      }
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

  int fd_;
  std::unique_ptr<char[]> buffer_;
  int error_ = 0;
};

} // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(fmt::format("cannot write {}: {}", tmp.string(), std::strerror(errno)));
  const auto fail = [&](const char* what, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error(fmt::format("cannot {} {}: {}", what, tmp.string(), std::strerror(err)));
  };
  FdBuffer buffer(fd);
  {
    std::ostream out(&buffer);
    try {
      write(out);
    } catch (...) {
      ::close(fd);
      ::unlink(tmp.c_str());
      throw;
    }
    out.flush();
  }
  if (buffer.error() != 0) fail("write", buffer.error());
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error(fmt::format("cannot flush {}: {}", tmp.string(), std::strerror(err)));
  }
  // A failed rename (the path a directory, or on another file system) leaves neither file.
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), std::strerror(err)));
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

void link_file_atomically(const std::filesystem::path& target, const std::filesystem::path& link) {
  const std::filesystem::path tmp = link.string() + ".tmp";
  std::error_code ignored;
  std::filesystem::remove(tmp, ignored);
  std::error_code linked;
  std::filesystem::create_hard_link(target, tmp, linked);
  if (linked) {
    std::filesystem::copy_file(target, tmp, std::filesystem::copy_options::overwrite_existing);
  }
  std::filesystem::rename(tmp, link);
}

} // namespace hilrig::rig
