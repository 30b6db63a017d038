#pragma once
// Output lines requested from one GPIO chip as a bulk (A/B/Z can change in one call).
// RAII: the request is released on destruction, after every line is driven to its
// inactive level (safe by default, DESIGN.md idea 7).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/rt_ports.hpp"
#include "drivers/gpiod/gpio_error.hpp"
#include "drivers/gpiod/line_settings.hpp"

namespace hilrig::gpiod {

class OutputRequest final : public RtOutputPort {
public:
  // chip: a name ("gpiochip0"), a path, a label or a number, as libgpiod looks it up.
  // Lines start at their inactive level (logical Low). Throws GpioError.
  OutputRequest(const std::string& chip, std::span<const unsigned> offsets, const LineSettings& settings,
                const std::string& consumer = "hilrig");
  ~OutputRequest() override;
  OutputRequest(const OutputRequest&) = delete;
  OutputRequest& operator=(const OutputRequest&) = delete;

  // One line by its index in `offsets`. No allocation: the RT loop calls this.
  void write(std::uint16_t index, Level level) noexcept override;
  // Every line at once, in one ioctl (levels.size() == line count).
  void write_all(std::span<const Level> levels) noexcept;
  void drive_inactive() noexcept;

  [[nodiscard]] std::size_t size() const { return offsets_.size(); }
  // A core LineOutput view of one line, for code written against the core interfaces.
  [[nodiscard]] LineOutput& line(std::size_t index);
  // Write errors seen (a failed ioctl is counted, never thrown, inside the RT loop).
  [[nodiscard]] std::uint64_t write_errors() const { return write_errors_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<unsigned> offsets_;
  std::vector<int> values_; // last written logical values, for bulk writes
  std::uint64_t write_errors_ = 0;
};

} // namespace hilrig::gpiod
