#pragma once
// The I/O the RT loop does, as two narrow interfaces the hardware drivers implement: write
// one output edge now; drain input edges the backend has timestamped. Neither may allocate,
// lock or log — each call is the I/O itself and nothing else.

#include <cstdint>
#include <span>

#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig {

// One output edge of a precomputed schedule; time is relative to the run's start.
struct ScheduledEdge {
  Nanos time;
  std::uint16_t line;
  Level level;
};

// An input edge as the backend timestamped it (the kernel's timestamp for gpiod).
struct InputEdge {
  Nanos time;
  std::uint16_t line;
  Level level;
};

class RtOutputPort {
public:
  virtual ~RtOutputPort() = default;
  virtual void write(std::uint16_t line, Level level) noexcept = 0;
};

class RtInputPort {
public:
  virtual ~RtInputPort() = default;
  // Fills `out` with edges seen since the last poll; never blocks.
  virtual std::size_t poll(std::span<InputEdge> out) noexcept = 0;
};

} // namespace hilrig
