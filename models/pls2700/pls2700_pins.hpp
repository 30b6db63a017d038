#pragma once
// The 2700's pins as core interfaces, and a helper that wires them to any bus that names
// its lines (the virtual bus: line() / analog()). A template, so the model never includes
// a driver. Unwired pins are null: an unwired stator reads 0 V (a transducer fault on that
// channel), an unwired input reads Low, an unwired output is not driven.
#include <array>
#include <string>
#include <string_view>

#include "core/analog.hpp"
#include "core/line.hpp"
#include "models/pls2700/setup.hpp"

namespace hilrig::models::pls2700 {

struct Pls2700Pins {
  std::array<const AnalogInput*, 2> stator_sin{};  // index 0 = channel 1: S4 (pins 5 / 7)
  std::array<const AnalogInput*, 2> stator_cos{};  // S3 (pins 6 / 8)
  std::array<LineInput*, 2> inputs{};              // 2742-18 IN1/IN2: High = energized
  std::array<LineOutput*, kOutputCount> outputs{}; // index 0 = OUT1; High = on
};

// Pin names, as a campaign's wiring names them: SIN1 COS1 SIN2 COS2 IN1 IN2 OUT1..OUT8.
[[nodiscard]] inline std::string sin_pin_name(int channel) { return "SIN" + std::to_string(channel); }
[[nodiscard]] inline std::string cos_pin_name(int channel) { return "COS" + std::to_string(channel); }
[[nodiscard]] inline std::string input_pin_name(int channel) { return "IN" + std::to_string(channel); }
[[nodiscard]] inline std::string output_pin_name(int output) { return "OUT" + std::to_string(output); }

// Wires every pin to the bus line named prefix + pin name (e.g. "pls.SIN1", "pls.OUT8").
template <class Bus> Pls2700Pins wire_pins(Bus& bus, std::string_view prefix = "pls.") {
  const auto name = [&](const std::string& pin) { return std::string(prefix) + pin; };
  Pls2700Pins pins;
  for (int ch = 1; ch <= 2; ++ch) {
    const auto i = static_cast<std::size_t>(ch - 1);
    pins.stator_sin[i] = &bus.analog(name(sin_pin_name(ch)));
    pins.stator_cos[i] = &bus.analog(name(cos_pin_name(ch)));
    pins.inputs[i] = &bus.line(name(input_pin_name(ch))).reader();
  }
  for (int n = 1; n <= kOutputCount; ++n) {
    pins.outputs[static_cast<std::size_t>(n - 1)] = &bus.line(name(output_pin_name(n))).driver();
  }
  return pins;
}

} // namespace hilrig::models::pls2700
