#pragma once
// Digital lines: the narrow interface every backend (virtual bus, libgpiod) implements.
// One driver, many readers; readers see levels and timestamped edges.

#include <cstdint>
#include <functional>

#include "core/time.hpp"

namespace hilrig {

enum class Level : std::uint8_t { Low = 0, High = 1 };

[[nodiscard]] constexpr Level operator!(Level l) { return l == Level::High ? Level::Low : Level::High; }
[[nodiscard]] constexpr Level level_of(bool high) { return high ? Level::High : Level::Low; }
[[nodiscard]] constexpr bool is_high(Level l) { return l == Level::High; }

struct Edge {
  Nanos time;
  Level level; // the level after the edge
  friend bool operator==(const Edge&, const Edge&) = default;
};

using EdgeHandler = std::function<void(const Edge&)>;

// The driving end of a line. set() takes effect at the backend's "now".
class LineOutput {
public:
  virtual ~LineOutput() = default;
  virtual void set(Level level) = 0;
  [[nodiscard]] virtual Level driven() const = 0;
};

// A reading end of a line.
class LineInput {
public:
  virtual ~LineInput() = default;
  [[nodiscard]] virtual Level level() const = 0;
  // Called for every edge this reader sees, in time order.
  virtual void on_edge(EdgeHandler handler) = 0;
};

} // namespace hilrig
