#pragma once
// Analog channels: a value that is a function of time, sampled by a reader at any
// instant (no fixed sample rate). A resolver's two stator signals are two of these.

#include <functional>

#include "core/time.hpp"

namespace hilrig {

class AnalogInput {
public:
  virtual ~AnalogInput() = default;
  [[nodiscard]] virtual double sample(Nanos t) const = 0;
};

using Waveform = std::function<double(Nanos)>;

} // namespace hilrig
