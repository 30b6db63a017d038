#pragma once
// How a rig line is requested from a GPIO chip: the electrical settings a wiring entry
// can ask for. Debounce is honoured only where the chip and the libgpiod API support it.

#include <optional>

#include "core/time.hpp"

namespace hilrig::gpiod {

enum class Bias { AsIs, Disabled, PullUp, PullDown };
enum class Drive { PushPull, OpenDrain, OpenSource };

struct LineSettings {
  bool active_low = false; // the board's pin is active when the wire is low
  Bias bias = Bias::AsIs;
  Drive drive = Drive::PushPull;
  std::optional<Nanos> debounce; // inputs only; libgpiod 1.6 cannot set it (see supports_debounce)
};

} // namespace hilrig::gpiod
