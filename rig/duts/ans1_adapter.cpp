#include "rig/duts/ans1_adapter.hpp"
#include "rig/duts/seed_phase.hpp"

#include <array>
#include <span>
#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/ans1/ans1.hpp"
#include "rig/duts/param_fields.hpp"
#include "signals/quadrature_waveform.hpp"

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
    const auto wired = [&](std::string_view pin) {
      const auto it = pin_to_line.find(pin);
      return it == pin_to_line.end() ? std::string() : it->second;
    };
    if (encoder_ != nullptr && !encoder_a_.empty() && wired(a::kPinA) == encoder_a_ &&
        wired(a::kPinB) == encoder_b_)
      pins.quad_waveform = encoder_;
    device_.attach(pins);
  }
  void sample_encoder(const std::string& a_line, const std::string& b_line,
                      signals::QuadratureWaveform& waveform) override {
    encoder_a_ = a_line;
    encoder_b_ = b_line;
    encoder_ = &waveform;
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    device_.host().write(static_cast<int>(word), value);
  }
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    return device_.host().read(static_cast<int>(word));
  }
  void scan_every_period() override { device_.scan_every_period(); }
  void power(bool on) override {
    if (on)
      device_.power_on();
    else
      device_.power_off();
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
  std::string encoder_a_, encoder_b_; // the lines a sampled encoder's waveform is on
  signals::QuadratureWaveform* encoder_ = nullptr;
};

// Every [MODEL] choice of models/ans1/README.md that is a field of Params, by the name a
// campaign's dut.params and `hilrig serve --param` use. Ranges: a scan of 10 us (master) or
// 50 us throughput (slave), docs/spec/ans1.md L187 (manual L572-L576); a model may scan 1 us .. 1 ms
// around them, not faster (a 1 ns scan is 10^9 events per virtual second). Speed update
// 14.6 ms (L820): 1 ms .. 1 s. Excitation: the band the ANS1 accepts from a resolver,
// 2.2 .. 7 kHz (docs/spec/ans1.md L60, manual L1455). The fault ratios bracket 1 (TR 0.9..1.0 is
// valid, L1456).
using F = ParamField<a::Params>;
const std::array kAns1Fields{
    F{"scan", &a::Params::master_scan_period, "master position-and-output scan period (10 us, 4.0)",
      between(1_us, 1_ms)},
    F{"slave_scan", &a::Params::slave_scan_period, "scan period as a slave (40 us: 50 us throughput, L576)",
      between(1_us, 1_ms)},
    F{"output_delay", &a::Params::output_delay, "scan to output pin (10 us: 10-20 us throughput, L572)",
      between(0_us, 1_ms)},
    // A detection-power knob (docs/power.md): up to 100 ms either way, longer than any pulse
    // width the shipped campaigns judge (a production cycle of 100 ms, ans1_counters).
    F{"output_off_skew", &a::Params::output_off_skew,
      "[KNOB] an output's turn-off delay minus its turn-on delay (0; one throughput for both edges, "
      "L572): > 0 stretches every ON pulse at the pin, < 0 shortens it",
      between(-100_ms, 100_ms)},
    F{"brake_sample_start", &a::Params::brake_sample_start,
      "brake debounce (a detection-power knob): the first of 16 1-ms samples after the application edge (16 "
      "ms, L1039)",
      between(1_ms, 1_s)},
    F{"speed_update", &a::Params::speed_update_period, "speed value update period (14.6 ms, L820)",
      between(1_ms, 1_s)},
    F{"excitation_hz", &a::Params::excitation_hz,
      "resolver excitation frequency (5 kHz; A35, L1455 2.2-7 kHz)", between(2'200.0, 7'000.0)},
    F{"excitation_amplitude", &a::Params::excitation_amplitude,
      "resolver reference peak, in the stator signals' unit (1.0)", between(0.001, 1000.0)},
    F{"resolver_min_ratio", &a::Params::resolver_min_ratio,
      "stator amplitude / reference below this is a Resolver Fault (0.75; an open coil drops below)",
      between(0.0, 1.0)},
    F{"resolver_max_ratio", &a::Params::resolver_max_ratio,
      "stator amplitude / reference above this is a Resolver Fault (1.25; TR 0.9-1.0 is valid, L1456)",
      between(1.0, 10.0)},
    F{"time_only_retrigger_restarts", &a::Params::time_only_retrigger_restarts,
      "a Time-Only output's From edge during its time restarts the timer (true, A39)"},
    // A detection-power knob (docs/power.md): the CB5 timer is 0 .. 32767 ms (L1961-L1962); an error
    // of up to 1 s either way keeps every programmable time meaningful (a sum <= 0 expires at once).
    F{"timer_error", &a::Params::timer_error,
      "[KNOB] added to every timed output's time (TP/TO timer, 4.7): a timer off its rate (0)",
      between(-1_s, 1_s)},
};

} // namespace

a::Params ans1_params(const DutParams& values) {
  return params_from(std::span<const F>(kAns1Fields), values);
}

DutInfo ans1_info() {
  DutInfo info;
  info.name = "ans1";
  info.description = "AMCI ANS1 AnyNET-I/O programmable limit switch (virtual model, docs/spec/ans1.md)";
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
  info.params = param_infos(std::span<const F>(kAns1Fields));
  for (const auto& v : a::kVariantNames)
    info.variants.push_back({std::string(v.name), std::string(v.description)});
  // Resolver faults on the stators the rig drives; the board detects them from the signal (the
  // stator amplitude sqrt(S^2 + C^2) against the reference outside resolver_min_ratio ..
  // resolver_max_ratio, [MODEL]) at its next excitation peak and scan.
  const std::string reaction =
      ": Resolver Fault (status bit 12, L418-419, L2299), outputs all off (HoldOuts 0) or held "
      "(HoldOuts 1, L1836), latched until Clear Errors with XFltLatch 0, cleared by itself with 1 "
      "(L1839); `until`: the signal is back";
  info.faults = {
      {"open_sin_coil",
       "the SIN stator open (amplitude 0): detected where the COS stator alone is below "
       "resolver_min_ratio" +
           reaction,
       FaultSite::OpenSin, true},
      {"open_cos_coil",
       "the COS stator open (amplitude 0): detected where the SIN stator alone is below "
       "resolver_min_ratio" +
           reaction,
       FaultSite::OpenCos, true},
      {"ratio_out_of_range",
       "both stators at `ratio` times the reference (a TR outside 0.9..1.0 without its reference "
       "module, L1456-1463): a fault outside resolver_min_ratio .. resolver_max_ratio" +
           reaction,
       FaultSite::StatorRatio, true},
  };
  info.power_cycle =
      "flash keeps the stored programs (CB15 Save Program, L2224) and the global parameters Save Global "
      "stored (CB2 position setup and presets, CB8 brake monitor, L2239); at power-up the ANS1 runs the "
      "program last saved or loaded [MODEL, L2236], else factory defaults (\"If power is cycled before these "
      "parameters are saved to a program, the ANS1 will power up with factory default settings\", L2236); "
      "the Machine Revolutions count is kept (non-volatile, L1215). The resolver is absolute (L768): the "
      "position is the same. Lost (RAM): unsaved programming, errors and Hardware Fault, a latched Resolver "
      "Fault and brake faults, forced outputs and inputs, the shift register, the other counters, speed, "
      "an encoder count (0 at power-up, A36) [MODEL]. While off: no scans, every output off, every status "
      "word 0; a Transmit already set at power-up is no edge";
  info.host = HostInterface{static_cast<std::size_t>(a::kHostWords), static_cast<std::size_t>(a::kHostWords),
                            true, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    a::Params p = ans1_params(params);
    p.scan_phase = phase_from_seed(seed, p.master_scan_period);
    const auto v = a::variant_from_name(variant);
    if (!v) throw std::invalid_argument("ans1 has no variant " + std::string(variant));
    return std::make_unique<Ans1Dut>(scheduler, p, *v);
  };
  return info;
}

} // namespace hilrig::duts
