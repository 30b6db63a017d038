#pragma once
// The ANS1's pins as core interfaces, and a helper that wires them to any bus that names its
// lines (the virtual bus: VirtualBus::line() / analog()). The helper is a template so that the
// model never includes a driver (DESIGN.md layering).
#include <array>
#include <string>
#include <string_view>

#include "core/analog.hpp"
#include "core/line.hpp"
#include "models/ans1/output_setup.hpp"
#include "signals/quadrature_waveform.hpp"

namespace hilrig::models::ans1 {

// Unwired pins are null: an unwired input reads Low (no current), an unwired output is not
// driven, an unwired stator reads 0 V (a resolver fault when the resolver is selected).
struct Ans1Pins {
  LineInput* quad_a = nullptr; // encoder A (4X with B)
  LineInput* quad_b = nullptr;
  LineInput* quad_z = nullptr; // Z is not decoded (L455); accepted and ignored
  // When A and B carry exactly this waveform (no faults, no delay; it outlives the device): the
  // count is sampled from it instead of decoded from every edge (docs/virtual-time.md, "Lines
  // carry waveforms"), unless the device scans every period (the oracle keeps the edges).
  signals::QuadratureWaveform* quad_waveform = nullptr;
  AnalogInput* stator_sin = nullptr;               // stator pair carrying TR * ref * sin(theta)
  AnalogInput* stator_cos = nullptr;               // stator pair carrying TR * ref * cos(theta)
  std::array<LineInput*, kInputCount> inputs{};    // index 0 = input 1; High = current flows
  std::array<LineOutput*, kOutputCount> outputs{}; // index 0 = output 1; High = on
};

// Pin names, as a campaign's wiring and the DUT adapter name them.
inline constexpr std::string_view kPinA = "A";
inline constexpr std::string_view kPinB = "B";
inline constexpr std::string_view kPinZ = "Z";
inline constexpr std::string_view kPinStatorSin = "SIN"; // S1-S3 [pair assignment is in a figure only]
inline constexpr std::string_view kPinStatorCos = "COS"; // S2-S4
[[nodiscard]] inline std::string input_pin_name(int input) { return "IN" + std::to_string(input); }
[[nodiscard]] inline std::string output_pin_name(int output) { return "OUT" + std::to_string(output); }

// Wires every pin to the bus line named prefix + pin name (e.g. "ans1.A", "ans1.IN3",
// "ans1.OUT16"): inputs become readers, outputs the driver, stators the analog channels.
template <class Bus> Ans1Pins wire_pins(Bus& bus, std::string_view prefix = "ans1.") {
  const auto name = [&](std::string_view pin) {
    std::string n(prefix);
    n += pin;
    return n;
  };
  Ans1Pins pins;
  pins.quad_a = &bus.line(name(kPinA)).reader();
  pins.quad_b = &bus.line(name(kPinB)).reader();
  pins.quad_z = &bus.line(name(kPinZ)).reader();
  pins.stator_sin = &bus.analog(name(kPinStatorSin));
  pins.stator_cos = &bus.analog(name(kPinStatorCos));
  for (int i = 1; i <= kInputCount; ++i) {
    pins.inputs[static_cast<std::size_t>(i - 1)] = &bus.line(name(input_pin_name(i))).reader();
  }
  for (int i = 1; i <= kOutputCount; ++i) {
    pins.outputs[static_cast<std::size_t>(i - 1)] = &bus.line(name(output_pin_name(i))).driver();
  }
  return pins;
}

// Wires only the pins a campaign's wiring names: pin_to_line maps a pin name (kPinA, "IN3",
// "OUT16", ...) to a bus line name (e.g. std::map<std::string, std::string, std::less<>>).
// Pins it does not name stay unwired.
template <class Bus, class Map> Ans1Pins wire_pins_by_map(Bus& bus, const Map& pin_to_line) {
  const auto line = [&](std::string_view pin) -> const std::string* {
    const auto it = pin_to_line.find(pin);
    return it == pin_to_line.end() ? nullptr : &it->second;
  };
  Ans1Pins pins;
  if (const auto* l = line(kPinA)) {
    pins.quad_a = &bus.line(*l).reader();
  }
  if (const auto* l = line(kPinB)) {
    pins.quad_b = &bus.line(*l).reader();
  }
  if (const auto* l = line(kPinZ)) {
    pins.quad_z = &bus.line(*l).reader();
  }
  if (const auto* l = line(kPinStatorSin)) {
    pins.stator_sin = &bus.analog(*l);
  }
  if (const auto* l = line(kPinStatorCos)) {
    pins.stator_cos = &bus.analog(*l);
  }
  for (int i = 1; i <= kInputCount; ++i) {
    if (const auto* l = line(input_pin_name(i))) {
      pins.inputs[static_cast<std::size_t>(i - 1)] = &bus.line(*l).reader();
    }
  }
  for (int i = 1; i <= kOutputCount; ++i) {
    if (const auto* l = line(output_pin_name(i))) {
      pins.outputs[static_cast<std::size_t>(i - 1)] = &bus.line(*l).driver();
    }
  }
  return pins;
}

} // namespace hilrig::models::ans1
