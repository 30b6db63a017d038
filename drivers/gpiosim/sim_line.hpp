#pragma once
// One line of a gpio-sim chip seen from the simulator's side, through sysfs
// (Documentation/admin-guide/gpio/gpio-sim.rst): CHIP_DIR/sim_gpioN/value reads the level the
// chip's user drives (or its pull, when nobody drives it), and writing "pull-up" or
// "pull-down" to CHIP_DIR/sim_gpioN/pull sets the level a user reading the line sees, with
// an edge event when it changes. CHIP_DIR is /sys/devices/platform/<dev_name>/<chip_name>.
// The file is opened once; each read and pull is one pread/pwrite at offset 0, so a poll
// loop makes one syscall per line and never allocates.

#include <stdexcept>
#include <string>

#include "core/line.hpp"

namespace hilrig::gpiosim {

// A sysfs file that cannot be opened, read or written; names the path and the reason.
class GpioSimError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The path of line `offset`'s attribute `attribute` ("value" or "pull") under chip_dir.
[[nodiscard]] std::string sim_line_path(const std::string& chip_dir, unsigned offset,
                                        const std::string& attribute);

// Reads the level the chip's user puts on the line (sim_gpioN/value).
class SimLineReader {
public:
  SimLineReader(const std::string& chip_dir, unsigned offset);
  ~SimLineReader();
  SimLineReader(const SimLineReader&) = delete;
  SimLineReader& operator=(const SimLineReader&) = delete;

  // Throws GpioSimError when the read fails or the file holds neither 0 nor 1.
  [[nodiscard]] Level read() const;
  [[nodiscard]] unsigned offset() const { return offset_; }
  [[nodiscard]] const std::string& path() const { return path_; }

private:
  int fd_ = -1;
  unsigned offset_;
  std::string path_;
};

// Sets the level the chip's user reads from the line (sim_gpioN/pull).
class SimLinePull {
public:
  SimLinePull(const std::string& chip_dir, unsigned offset);
  ~SimLinePull();
  SimLinePull(const SimLinePull&) = delete;
  SimLinePull& operator=(const SimLinePull&) = delete;

  // High writes "pull-up", Low "pull-down". Throws GpioSimError when the write fails.
  void pull(Level level);
  [[nodiscard]] unsigned offset() const { return offset_; }
  [[nodiscard]] const std::string& path() const { return path_; }

private:
  int fd_ = -1;
  unsigned offset_;
  std::string path_;
};

} // namespace hilrig::gpiosim
