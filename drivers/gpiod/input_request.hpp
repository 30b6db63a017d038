#pragma once
// Input lines requested from one GPIO chip with edge events on both edges. Each edge
// carries the kernel's timestamp (CLOCK_MONOTONIC, with libgpiod 1.6 and 2.x alike),
// so capture precision does not depend on how soon the rig polls.

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

class InputRequest final : public RtInputPort {
public:
  InputRequest(const std::string& chip, std::span<const unsigned> offsets, const LineSettings& settings,
               const std::string& consumer = "hilrig");
  ~InputRequest() override;
  InputRequest(const InputRequest&) = delete;
  InputRequest& operator=(const InputRequest&) = delete;

  // Drains pending edge events of every line without blocking; `line` in each InputEdge is
  // the index in `offsets`. No allocation: the RT loop calls this.
  std::size_t poll(std::span<InputEdge> out) noexcept override;
  // Current logical level of one line (a syscall: not for the RT loop's hot path).
  [[nodiscard]] Level level(std::size_t index) const;
  // File descriptors to wait on (poll/epoll) outside the RT loop, one per line. With
  // libgpiod 2.x one request carries every line, so the entries are the same descriptor.
  [[nodiscard]] std::span<const int> event_fds() const { return fds_; }
  [[nodiscard]] std::size_t size() const { return offsets_.size(); }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<unsigned> offsets_;
  std::vector<int> fds_;
};

// True when this build's libgpiod can set a hardware debounce period (2.x only).
[[nodiscard]] bool supports_debounce();

} // namespace hilrig::gpiod
