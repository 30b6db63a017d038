#pragma once
// A virtual full-duplex serial link between end A and end B. Each byte takes
// SerialFormat::char_time() on the wire; bytes queue behind each other per direction, the
// two directions independent. A byte reaches the far end's handlers (and the trace, under
// the link's name with its direction) when its stop bit ends. A dropped byte still takes its
// time on the wire and is neither delivered nor traced; a corrupted byte is delivered and
// traced as the value the hook returns. The link must outlive the scheduler's pending events.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/scheduler.hpp"
#include "core/serial.hpp"
#include "core/trace.hpp"

namespace hilrig::virt {

class SerialLink {
public:
  SerialLink(Scheduler& scheduler, std::string name, SerialFormat format, TraceRecorder* trace);
  ~SerialLink();

  [[nodiscard]] ByteLink& end_a();
  [[nodiscard]] ByteLink& end_b();
  [[nodiscard]] const SerialFormat& format() const;

  // Fault hooks, asked per byte: corrupt returns the byte that arrives instead;
  // drop returns true to lose it.
  using Corrupt = std::function<std::uint8_t(SerialDirection, std::uint8_t)>;
  using Drop = std::function<bool(SerialDirection, std::uint8_t)>;
  void set_corrupt(Corrupt corrupt);
  void set_drop(Drop drop);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace hilrig::virt
