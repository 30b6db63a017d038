#include "models/ans1/enable.hpp"

namespace hilrig::models::ans1 {

bool speed_enabled(std::int16_t low, std::int16_t high, std::int16_t speed) {
  if (low == 0 && high == 0) {
    return true;
  }
  if (low < high) {
    return low <= speed && speed <= high;
  }
  if (low > high) {
    return speed < high || speed > low;
  }
  return speed == low;
}

std::uint16_t anding_mask(const OutputSetup& setup, AndingMode mode) {
  std::uint16_t mask = 0;
  for (int i = 0; i < kInputCount; ++i) {
    if (setup.anding[static_cast<std::size_t>(i)] == mode) {
      mask = static_cast<std::uint16_t>(mask | (1U << static_cast<unsigned>(i)));
    }
  }
  return mask;
}

bool in_window(std::uint16_t p, std::uint16_t low, std::uint16_t high) {
  if (low <= high) {
    return low <= p && p <= high;
  }
  return p >= low || p <= high;
}

bool PulseLatch::step(int pair, std::uint16_t active_inputs, std::uint16_t pulse_inputs) {
  if (pair != pair_) {
    latched_ = 0;
    pair_ = pair;
  }
  if (pair >= 0) {
    latched_ = static_cast<std::uint16_t>(latched_ | (active_inputs & pulse_inputs));
  }
  return (latched_ & pulse_inputs) == pulse_inputs;
}

bool WindowLatch::step(bool inside, bool input_active) {
  if (inside && !inside_) {
    w_ = false;
  }
  inside_ = inside;
  if (inside && input_active) {
    w_ = true;
  }
  return w_;
}

} // namespace hilrig::models::ans1
