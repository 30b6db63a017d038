#include "rig/duts/smd23e_dut.hpp"
#include "rig/duts/seed_phase.hpp"

#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/smd23e/smd23e.hpp"
#include "rig/duts/param_fields.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace m = hilrig::models::smd23e;

// While idle the shaft sensor looks for a new motion this often (motion started by the
// model itself, e.g. after a homing pause). While moving it wakes at each step's exact time.
// When the model has nothing pending that could move the shaft (Smd23e::at_rest_until_told)
// it does not look until an outside call: each such call runs follow(), which starts the looks
// again from its instant, and the looks skipped in between would each have found the shaft
// where it was, emitted nothing and scheduled the next (no run: watch_encoder() does nothing).
constexpr Nanos kIdlePoll{50'000};

class Smd23eDut final : public Dut {
public:
  Smd23eDut(Scheduler& scheduler, const m::Params& params) : sched_(scheduler), device_(scheduler, params) {}
  ~Smd23eDut() override { sched_.cancel(wake_); }
  Smd23eDut(const Smd23eDut&) = delete;
  Smd23eDut& operator=(const Smd23eDut&) = delete;

  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    const auto enc_a = pin_to_line.find(kSmd23eEncoderAPin);
    const auto enc_b = pin_to_line.find(kSmd23eEncoderBPin);
    if ((enc_a == pin_to_line.end()) != (enc_b == pin_to_line.end()))
      throw std::invalid_argument("smd23e: wire both ENC_A and ENC_B or neither");
    if (enc_a != pin_to_line.end())
      device_.connect_encoder(bus.line(enc_a->second).reader(), bus.line(enc_b->second).reader());
    for (const auto& [pin, line] : pin_to_line) {
      if (pin == kSmd23eEncoderAPin || pin == kSmd23eEncoderBPin) continue;
      if (pin == kSmd23eStepPin) {
        step_ = &bus.line(line).driver();
      } else if (pin == kSmd23eDirPin) {
        dir_ = &bus.line(line).driver();
      } else if (pin.size() == 3 && pin.starts_with("IN") && pin[2] >= '1' && pin[2] <= '3') {
        LineInput& in = bus.line(line).reader();
        device_.connect_input(pin[2] - '0', in);
        // The model's handler runs first; then the sensor looks for motion the edge started.
        in.on_edge([this](const Edge&) { follow(); });
      } else {
        throw std::invalid_argument("smd23e has no pin " + pin);
      }
    }
    follow();
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    if (word >= m::kWords) throw std::out_of_range("smd23e has 10 output words");
    staged_[word] = value;
    if (word == 0) {
      device_.write_outputs(staged_);
      follow();
    }
  }

  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    if (word >= m::kWords) throw std::out_of_range("smd23e has 10 input words");
    return device_.input_words()[word];
  }

  // smd23e_info().faults: 0 over_temperature, 1 temperature_warning.
  void device_fault(std::size_t fault, bool active) override {
    if (fault == 0)
      device_.set_over_temperature(active);
    else if (fault == 1)
      device_.set_temperature_warning(active);
    else
      throw std::logic_error("smd23e: no such device fault");
    follow(); // an over-temperature stops the step train
  }

  void power(bool on) override {
    if (on)
      device_.power_on();
    else
      device_.power_off();
    follow(); // power off stops the step train where it is
  }

private:
  // Emits the steps the shaft has turned since the last call, then sleeps until the next.
  void follow() {
    sched_.cancel(wake_);
    const Nanos now = sched_.now();
    const std::int64_t here = device_.shaft_steps(now);
    while (emitted_ != here) {
      const bool cw = here > emitted_;
      if (dir_ != nullptr && cw != dir_cw_) dir_->set(level_of(cw));
      dir_cw_ = cw;
      step_level_ = !step_level_;
      if (step_ != nullptr) step_->set(step_level_);
      emitted_ += cw ? 1 : -1;
    }
    device_.watch_encoder();
    if (device_.at_rest_until_told()) {
      wake_ = {};
      return;
    }
    wake_ = sched_.at(next_wake(now), [this] { follow(); });
  }

  // The exact time the present run issues its next whole step (the model's own rule), or the
  // idle poll, whichever is sooner.
  [[nodiscard]] Nanos next_wake(Nanos now) const {
    const Nanos next = now + kIdlePoll;
    const Nanos t = device_.next_step_time(now);
    if (t <= now) return now + Nanos{1};
    return t < next ? t : next;
  }

  Scheduler& sched_;
  m::Smd23e device_;
  m::Words staged_{};
  LineOutput* step_ = nullptr;
  LineOutput* dir_ = nullptr;
  Level step_level_ = Level::Low;
  bool dir_cw_ = false;
  std::int64_t emitted_ = 0;
  EventId wake_{};
};

// Every [MODEL] choice of models/smd23e/README.md (Params), by the name a campaign's
// dut.params and `hilrig serve --param` use. Ranges: the homing pause is 2 s (docs/spec/smd23e.md
// T2, manual L1327): 0 .. 60 s; the heartbeat ~500 ms (T3, L2888) and the idle delay 1.5 s
// (T1, L781) within what a run observes; an input delay [A] 0 .. 1 s; the S-ramp fraction is
// a fraction; a stall threshold up to one encoder turn (1024 counts); the fault knobs within
// what keeps a move a move (1 lost step in 1 .. 1,000,000; ramps at 0.01 .. 100 x A and D;
// stops 0 .. 10 s late).
using F = ParamField<m::Params>;
const std::array kSmd23eFields{
    F{"has_encoder", &m::Params::has_encoder, "an E unit with the internal 1024-count encoder (1.1)"},
    F{"m12", &m::Params::m12, "an M12 unit: inputs 1 and 2 only (1.1)"},
    F{"heartbeat_half_period", &m::Params::heartbeat_half_period,
      "SW2 bit 11 heartbeat half period (T3, 500 ms)", between(1_ms, 10_s)},
    F{"homing_pause", &m::Params::homing_pause, "pause after each homing stop (T2, 2 s)",
      between(0_us, 60_s)},
    F{"idle_current_delay", &m::Params::idle_current_delay,
      "no motion this long drops to the idle current (T1, 1.5 s)", between(0_us, 60_s)},
    F{"input_delay", &m::Params::input_delay, "input edge to its effect [A 2.2] (0)", between(0_us, 1_s)},
    F{"scurve_linear_fraction", &m::Params::scurve_linear_fraction,
      "linear fraction of a trapezoidal S-ramp, J = 2..5000 [U 3.3] (0.5: the manual's +33 %)",
      between(0.0, 1.0)},
    F{"stop_input_level_sensitive", &m::Params::stop_input_level_sensitive,
      "Stop Jog/Registration input acts on its level at the minimum distance (true) or on an edge only [U 9 "
      "#4]"},
    F{"capture_on_any_transition", &m::Params::capture_on_any_transition,
      "Start Indexed captures the encoder on every transition (true) or rising only [U 9 #5]"},
    F{"stall_threshold_counts", &m::Params::stall_threshold_counts,
      "stall when the shaft lags the steps by more than this many encoder counts [U 2.3] (16)",
      between(0.0, 1024.0)},
    F{"dwell_after_last_segment", &m::Params::dwell_after_last_segment,
      "a Dwell move also dwells after its last segment [U 9 #9] (false)"},
    F{"report_present_current", &m::Params::report_present_current,
      "input word 8 shows the idle-reduced current (true) or the configured one [U 6.6]"},
    F{"sw2_bit13_as_figure", &m::Params::sw2_bit13_as_figure,
      "SW2 bit 13 as the example dump's figure shows it, not as the text [U 9 #1] (false)"},
    F{"netloss_at_powerup", &m::Params::netloss_at_powerup,
      "Network Lost set at power-up, as the example dump [U 9 #34] (false)"},
    F{"flash_config_valid", &m::Params::flash_config_valid,
      "power up configured from flash: v_s 100, 2048 steps/turn, encoder on, 2.0 A, 50 % idle (false)"},
    F{"wrong_accel_factor", &m::Params::wrong_accel_factor,
      "variant wrong-acceleration: ramps at this x the programmed A and D (0.5)", between(0.01, 100.0)},
    F{"lost_step_interval", &m::Params::lost_step_interval,
      "variant lost-steps: the shaft misses one step in this many issued (100)", between(1.0, 1'000'000.0)},
    F{"late_stop_delay", &m::Params::late_stop_delay, "variant late-stop: how late stops act (20 ms)",
      between(0_us, 10_s)},
    // A detection-power knob (docs/power.md): up to half as fast or half as slow again.
    F{"step_clock_error", &m::Params::step_clock_error,
      "[KNOB] the step time base off by this fraction: every motion profile (3.2, 3.3) lasts (1 + e) x "
      "its planned time (0)",
      between(-0.5, 0.5)},
};

} // namespace

m::Params smd23e_params(const DutParams& values) {
  return params_from(std::span<const F>(kSmd23eFields), values);
}

DutInfo smd23e_info() {
  DutInfo info;
  info.name = "smd23e";
  info.description =
      "AMCI SMD23E integrated stepper indexer/driver/motor (virtual model, docs/spec/smd23e.md)";
  for (int i = 1; i <= 3; ++i)
    info.pins.push_back({"IN" + std::to_string(i), PinDirection::Input,
                         "discrete input " + std::to_string(i) + " (High = current flows)", false});
  info.pins.push_back({kSmd23eStepPin, PinDirection::Output,
                       "shaft sensor: one edge (either level) per step the shaft turns", false});
  info.pins.push_back({kSmd23eDirPin, PinDirection::Output,
                       "shaft sensor: High while the shaft steps CW, Low CCW (Low at power-up)", false});
  info.pins.push_back({kSmd23eEncoderAPin, PinDirection::Input,
                       "the shaft's encoder, channel A, when a rig plant turns the shaft (virtual only): "
                       "1024 counts a turn; stall detection compares it with the steps",
                       false});
  info.pins.push_back(
      {kSmd23eEncoderBPin, PinDirection::Input, "the shaft's encoder, channel B (see ENC_A)", false});
  info.params = param_infos(std::span<const F>(kSmd23eFields));
  info.variants.push_back({"nominal", "as specified"});
  for (const std::string_view v : m::fault_names())
    info.variants.push_back({std::string(v), std::string(m::fault_description(*m::fault_from_name(v)))});
  info.faults = {
      {"over_temperature",
       "the driver over temperature: with the driver enabled, motor power is removed (L565), the step "
       "train stops at once and the position is invalid, SW2 bit 7 Driver Fault set (L2892, L2922); "
       "`until`: the unit has cooled. Reset Errors with LSW bit 10 and DriveEn 0 clears it only once "
       "cooled (L2471, L2922, [MODEL]); the motor has current again when DriveEn is set (L2946)",
       FaultSite::Board, true},
      {"temperature_warning",
       "CPU above 90 C (heatsink near 83 C): SW2 bit 4 Temperature Warning set, motion goes on "
       "(L564, L2895); `until`: cooled, the bit clears",
       FaultSite::Board, true},
  };
  info.power_cycle =
      "flash survives: a configuration saved with Save Configuration (Config Word bit 10) or "
      "flash_config_valid "
      "is loaded at power-up, else SW1 0x6408 (L1836, L2235, L2284, L2372); an assembled move saved with LSW "
      "bit 5 is restored (L1132, L1205). RAM is lost: an unsaved configuration and assembled move (L2235, "
      "L1132), every error bit, and the lock-out after a flash save, which lasts until power is cycled "
      "(L2331, L2476). Command Mode (L2243), Motor and Encoder Position 0 and Position Invalid [MODEL: no "
      "absolute position]. While off [MODEL]: the step train stops where it is, input words read 0, inputs "
      "and output words are unseen (words held at power-up are no edge); an over-temperature still present "
      "faults the driver again";
  info.host = HostInterface{m::kWords, m::kWords, false, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    m::Params p = smd23e_params(params);
    p.heartbeat_phase = phase_from_seed(seed, 2 * p.heartbeat_half_period);
    if (variant != "nominal") {
      const auto f = m::fault_from_name(variant);
      if (!f) throw std::invalid_argument("smd23e has no variant " + std::string(variant));
      p.fault = *f;
    }
    return std::make_unique<Smd23eDut>(scheduler, p);
  };
  return info;
}

} // namespace hilrig::duts
