#include "rig/duts/ans1_adapter.hpp"

#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/ans1/ans1.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace a = hilrig::models::ans1;

class Ans1Dut final : public Dut {
public:
  Ans1Dut(Scheduler& scheduler, const a::Params& params, a::Variant variant)
      : device_(scheduler, params, variant) {}

  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    a::Ans1Pins pins;
    for (const auto& [pin, line] : pin_to_line) {
      if (pin == a::kPinA)
        pins.quad_a = &bus.line(line).reader();
      else if (pin == a::kPinB)
        pins.quad_b = &bus.line(line).reader();
      else if (pin == a::kPinZ)
        pins.quad_z = &bus.line(line).reader();
      else if (pin == a::kPinStatorSin)
        pins.stator_sin = &bus.analog(line);
      else if (pin == a::kPinStatorCos)
        pins.stator_cos = &bus.analog(line);
      else if (!wire_point(bus, pin, line, pins))
        throw std::invalid_argument("ans1 has no pin " + pin);
    }
    device_.attach(pins);
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    device_.host().write(static_cast<int>(word), value);
  }
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    return device_.host().read(static_cast<int>(word));
  }

private:
  static bool wire_point(virt::VirtualBus& bus, const std::string& pin, const std::string& line,
                         a::Ans1Pins& pins) {
    for (int i = 1; i <= a::kInputCount; ++i) {
      if (pin == a::input_pin_name(i)) {
        pins.inputs[static_cast<std::size_t>(i - 1)] = &bus.line(line).reader();
        return true;
      }
    }
    for (int i = 1; i <= a::kOutputCount; ++i) {
      if (pin == a::output_pin_name(i)) {
        pins.outputs[static_cast<std::size_t>(i - 1)] = &bus.line(line).driver();
        return true;
      }
    }
    return false;
  }

  a::Ans1 device_;
};

} // namespace

DutInfo ans1_info() {
  DutInfo info;
  info.name = "ans1";
  info.description = "AMCI ANS1 AnyNET-I/O programmable limit switch (virtual model, spec/ans1.md)";
  info.pins = {
      {std::string(a::kPinA), PinDirection::Input, "quadrature A (when CB2 selects the encoder)", false},
      {std::string(a::kPinB), PinDirection::Input, "quadrature B", false},
      {std::string(a::kPinZ), PinDirection::Input, "quadrature Z (accepted, not decoded)", false},
      {std::string(a::kPinStatorSin), PinDirection::Input, "resolver stator S1-S3", true},
      {std::string(a::kPinStatorCos), PinDirection::Input, "resolver stator S2-S4", true},
  };
  for (int i = 1; i <= a::kInputCount; ++i)
    info.pins.push_back(
        {a::input_pin_name(i), PinDirection::Input, "discrete input " + std::to_string(i), false});
  for (int i = 1; i <= a::kOutputCount; ++i)
    info.pins.push_back({a::output_pin_name(i), PinDirection::Output, "output " + std::to_string(i), false});
  const a::Params d{};
  // Ranges: a scan of 10 us (master) or 50 us throughput (slave), spec/ans1.md L187 (manual
  // L572-L576); a model may scan 1 us .. 1 ms around them, not faster (a 1 ns scan is 10^9 events
  // per virtual second). Speed update 14.6 ms (L820): 1 ms .. 1 s. Excitation: the band the ANS1
  // accepts from a resolver, 2.2 .. 7 kHz (spec/ans1.md L60, manual L1455).
  info.params = {
      {"scan", ParamKind::Duration, d.master_scan_period, "master position-and-output scan period",
       between(1_us, 1_ms)},
      {"slave_scan", ParamKind::Duration, d.slave_scan_period, "scan period as a slave", between(1_us, 1_ms)},
      {"output_delay", ParamKind::Duration, d.output_delay, "scan to output pin", between(0_us, 1_ms)},
      {"speed_update", ParamKind::Duration, d.speed_update_period, "speed value update period",
       between(1_ms, 1_s)},
      {"excitation_hz", ParamKind::Number, d.excitation_hz, "resolver excitation frequency",
       between(2'200.0, 7'000.0)},
  };
  for (const auto& v : a::kVariantNames)
    info.variants.push_back({std::string(v.name), v.variant == a::Variant::Correct
                                                      ? "as specified"
                                                      : "wrong on purpose (models/ans1/variants.hpp)"});
  info.host = HostInterface{static_cast<std::size_t>(a::kHostWords), static_cast<std::size_t>(a::kHostWords),
                            true, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t /*seed*/) -> std::unique_ptr<Dut> {
    a::Params p;
    p.master_scan_period = params.duration("scan");
    p.slave_scan_period = params.duration("slave_scan");
    p.output_delay = params.duration("output_delay");
    p.speed_update_period = params.duration("speed_update");
    p.excitation_hz = params.number("excitation_hz");
    const auto v = a::variant_from_name(variant);
    if (!v) throw std::invalid_argument("ans1 has no variant " + std::string(variant));
    return std::make_unique<Ans1Dut>(scheduler, p, *v);
  };
  return info;
}

} // namespace hilrig::duts
