#include "drivers/gpiosim/sim_line.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

namespace hilrig::gpiosim {

namespace {

std::string why(const std::string& what, const std::string& path, int err) {
  return "gpio-sim: " + what + " " + path + ": " + std::strerror(err);
}

int open_or_throw(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw GpioSimError(why("cannot open", path, errno));
  return fd;
}

} // namespace

std::string sim_line_path(const std::string& chip_dir, unsigned offset, const std::string& attribute) {
  std::string path = chip_dir;
  if (!path.empty() && path.back() != '/') path += '/';
  return path + "sim_gpio" + std::to_string(offset) + "/" + attribute;
}

SimLineReader::SimLineReader(const std::string& chip_dir, unsigned offset)
    : offset_(offset), path_(sim_line_path(chip_dir, offset, "value")) {
  fd_ = open_or_throw(path_, O_RDONLY);
}

SimLineReader::~SimLineReader() {
  if (fd_ >= 0) ::close(fd_);
}

Level SimLineReader::read() const {
  char text[8] = {};
  // A sysfs attribute is re-read from the start: offset 0 each time.
  const ssize_t n = ::pread(fd_, text, sizeof(text), 0);
  if (n < 0) throw GpioSimError(why("cannot read", path_, errno));
  if (n >= 1 && text[0] == '1') return Level::High;
  if (n >= 1 && text[0] == '0') return Level::Low;
  throw GpioSimError("gpio-sim: " + path_ + " holds '" + std::string(text, static_cast<std::size_t>(n)) +
                     "', not 0 or 1");
}

SimLinePull::SimLinePull(const std::string& chip_dir, unsigned offset)
    : offset_(offset), path_(sim_line_path(chip_dir, offset, "pull")) {
  fd_ = open_or_throw(path_, O_WRONLY);
}

SimLinePull::~SimLinePull() {
  if (fd_ >= 0) ::close(fd_);
}

void SimLinePull::pull(Level level) {
  const std::string_view text = is_high(level) ? "pull-up" : "pull-down";
  const ssize_t n = ::pwrite(fd_, text.data(), text.size(), 0);
  if (n != static_cast<ssize_t>(text.size())) throw GpioSimError(why("cannot write", path_, errno));
}

} // namespace hilrig::gpiosim
