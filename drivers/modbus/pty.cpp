#include "drivers/modbus/pty.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace hilrig::drivers::modbus {

namespace {
[[noreturn]] void fail(const char* what) {
  throw std::runtime_error(std::string("pty: ") + what + ": " + std::strerror(errno));
}
} // namespace

Pty::Pty() {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master_ < 0) {
    fail("posix_openpt");
  }
  std::array<char, 128> name{};
  if (::grantpt(master_) != 0 || ::unlockpt(master_) != 0 ||
      ::ptsname_r(master_, name.data(), name.size()) != 0) {
    const int err = errno;
    ::close(master_);
    errno = err;
    fail("cannot set up the slave");
  }
  slave_path_ = name.data();
  slave_ = ::open(slave_path_.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (slave_ < 0) {
    const int err = errno;
    ::close(master_);
    errno = err;
    fail("cannot open the slave");
  }
  // Raw from the start: no echo or line editing may touch a frame before a client configures
  // the port itself.
  termios tio{};
  if (::tcgetattr(slave_, &tio) == 0) {
    ::cfmakeraw(&tio);
    ::tcsetattr(slave_, TCSANOW, &tio);
  }
}

Pty::~Pty() {
  ::close(slave_);
  ::close(master_);
}

} // namespace hilrig::drivers::modbus
