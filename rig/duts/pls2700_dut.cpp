#include "rig/duts/pls2700_dut.hpp"
#include "rig/duts/seed_phase.hpp"

#include <array>
#include <stdexcept>

#include <fmt/format.h>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/pls2700/params_check.hpp"
#include "models/pls2700/pls2700.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace p = hilrig::models::pls2700;

class Pls2700Dut final : public Dut {
public:
  Pls2700Dut(Scheduler& scheduler, p::ModelVariant model, const p::Params& params, p::Fault fault)
      : device_(scheduler, model, params, fault) {}

  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    p::Pls2700Pins pins;
    for (const auto& [pin, line] : pin_to_line) {
      if (!wire(bus, pin, line, pins)) throw std::invalid_argument("pls2700 has no pin " + pin);
    }
    device_.attach(pins);
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    if (word == kPls2700BtwSendWord) {
      // Length 0 sends the whole 64-word file (L1269): words never written are 0000h, which
      // the module rejects as a command word (21h, L1411), its answer to a zero length
      // used without 64 words. Longer lengths are refused when the campaign is read.
      const std::size_t length = value == 0 ? btw_.size() : value;
      if (length <= btw_.size()) device_.write_btw(std::span<const std::uint16_t>(btw_.data(), length));
    } else if (word - 1 < btw_.size()) {
      btw_[word - 1] = value;
    }
  }
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    if (word < device_.btr_words()) return device_.btr_word(word);
    if (word == kPls2700ErrorWord) return device_.error_byte();
    if (word == kPls2700SingleTransferWord) return device_.single_transfer_word();
    return 0;
  }
  // The front panel (pls2700_info().panel): the Program switch, and CLEAR while channel 1's or
  // 2's position is displayed (AutoZero). A key the module ignores (Display Mode, a channel it
  // lacks, a latched fault) does nothing, as on the board.
  void panel(std::size_t action) override {
    switch (action) {
    case 0:
      device_.set_program_switch(true);
      return;
    case 1:
      device_.set_program_switch(false);
      return;
    case 2:
    case 3:
      (void)device_.autozero(static_cast<int>(action) - 1);
      return;
    default:
      if (action < 4 + p::kOutputCount) { // delete_last_pair_N
        const int output = static_cast<int>(action) - 3;
        (void)device_.keyboard_delete_pair(output, device_.setup().outputs[action - 4].pair_count);
        return;
      }
      throw std::logic_error("pls2700: no front-panel action " + std::to_string(action));
    }
  }

  void power(bool on) override {
    if (on)
      device_.power_on();
    else
      device_.power_off();
  }

private:
  static bool wire(virt::VirtualBus& bus, const std::string& pin, const std::string& line,
                   p::Pls2700Pins& pins) {
    for (int ch = 1; ch <= 2; ++ch) {
      const auto i = static_cast<std::size_t>(ch - 1);
      if (pin == p::sin_pin_name(ch)) {
        pins.stator_sin[i] = &bus.analog(line);
        return true;
      }
      if (pin == p::cos_pin_name(ch)) {
        pins.stator_cos[i] = &bus.analog(line);
        return true;
      }
      if (pin == p::input_pin_name(ch)) {
        pins.inputs[i] = &bus.line(line).reader();
        return true;
      }
    }
    for (int n = 1; n <= p::kOutputCount; ++n) {
      if (pin == p::output_pin_name(n)) {
        pins.outputs[static_cast<std::size_t>(n - 1)] = &bus.line(line).driver();
        return true;
      }
    }
    return false;
  }

  p::Pls2700 device_;
  std::array<std::uint16_t, p::kMaxBtwWords> btw_{};
};

} // namespace

p::ModelVariant pls2700_model(const DutParams& params) {
  const auto model = p::model_from_name(params.text("model"));
  if (!model) throw std::invalid_argument("pls2700 has no model " + params.text("model"));
  return *model;
}

p::Params pls2700_params(const DutParams& params) {
  p::Params q;
  q.excitation_hz = params.number("excitation_hz");
  q.excitation_amplitude = params.number("excitation_amplitude");
  q.min_stator_ratio = params.number("min_stator_ratio");
  q.max_stator_ratio = params.number("max_stator_ratio");
  q.tach_32ms_on_single_channel = params.boolean("tach_32ms");
  q.wrap_pairs = params.boolean("wrap_pairs");
  q.equal_pair_full_turn = params.boolean("equal_pair_full_turn");
  const std::string& reverse = params.text("reverse_advance");
  if (reverse != "signed" && reverse != "disabled")
    throw std::invalid_argument("pls2700 reverse_advance must be signed or disabled");
  q.reverse_advance = reverse == "signed" ? p::ReverseAdvance::Signed : p::ReverseAdvance::Disabled;
  q.fault_turns_off_all_outputs = params.boolean("fault_all_outputs");
  q.power_up_mask = static_cast<std::uint8_t>(params.integer("power_up_mask") & 0xFF);
  q.output_delay = params.duration("output_delay");
  q.output_off_skew = params.duration("output_off_skew");
  q.input_delay = params.duration("input_delay");
  q.advance_speed_window = params.duration("advance_speed_window");
  q.program_switch_at_program = params.text("program_switch") == "program";
  q.program_jumper_fitted = params.boolean("program_jumper");
  return q;
}

DutInfo pls2700_info() {
  DutInfo info;
  info.name = "pls2700";
  info.description =
      "AMCI Series 2700 programmable limit switch, 7 models (virtual model, docs/spec/pls2700.md)";
  for (int ch = 1; ch <= 2; ++ch) {
    const std::string c = std::to_string(ch);
    info.pins.push_back(
        {p::sin_pin_name(ch), PinDirection::Input, "resolver " + c + " SIN stator (S4)", true});
    info.pins.push_back(
        {p::cos_pin_name(ch), PinDirection::Input, "resolver " + c + " COS stator (S3)", true});
  }
  for (int ch = 1; ch <= 2; ++ch)
    info.pins.push_back({p::input_pin_name(ch), PinDirection::Input,
                         "2742-18 DC input " + std::to_string(ch) + " (High = energized)", false});
  for (int n = 1; n <= p::kOutputCount; ++n)
    info.pins.push_back(
        {p::output_pin_name(n), PinDirection::Output, "limit output " + std::to_string(n), false});
  const p::Params d{};
  // Ranges: the manual gives no reference frequency, amplitude or fault threshold (docs/spec/pls2700.md
  // L632, [X]). The update clock is locked to the reference, so a reference is taken only where
  // its peaks fall on the 200/400 us update grid (L377; models/pls2700/params_check.hpp, checked
  // with the model by `conflict` below): multiples of 1,250 Hz up to 10 kHz, the common resolver
  // references. Stator/reference ratios 0 .. 10, min <= max; the mask is 8 outputs (R-M-2); the
  // 2742-18 input delay is at most 3 ms (L1724); the update period is 200/400 us (L377).
  const std::int64_t one_channel_step = p::reference_step_hz(p::traits(p::ModelVariant::M2741).update_period);
  const std::int64_t two_channel_step = p::reference_step_hz(p::traits(p::ModelVariant::M2742).update_period);
  info.params = {
      {"model", ParamKind::Text, std::string("2742"), "2731, 2731-04, 2732, 2732-04, 2741, 2742, 2742-18",
       one_of({"2731", "2731-04", "2732", "2732-04", "2741", "2742", "2742-18"})},
      {"excitation_hz", ParamKind::Number, d.excitation_hz,
       fmt::format(
           "resolver reference frequency [X]; its half period divides the update period (L377): a "
           "multiple of {} Hz on a 2731, 2731-04 or 2741 (200 us), of {} Hz on the two-channel models "
           "(400 us)",
           one_channel_step, two_channel_step),
       between(static_cast<double>(two_channel_step), static_cast<double>(p::kMaxReferenceHz))},
      {"excitation_amplitude", ParamKind::Number, d.excitation_amplitude, "reference peak [X]",
       between(0.001, 100.0)},
      {"min_stator_ratio", ParamKind::Number, d.min_stator_ratio,
       "transducer fault below this stator/ref (at most max_stator_ratio)", between(0.0, 10.0)},
      {"max_stator_ratio", ParamKind::Number, d.max_stator_ratio,
       "transducer fault above this stator/ref (at least min_stator_ratio)", between(0.0, 10.0)},
      {"tach_32ms", ParamKind::Boolean, d.tach_32ms_on_single_channel, "tach code 0 = 32 ms on 27x1", {}},
      {"wrap_pairs", ParamKind::Boolean, d.wrap_pairs, "ON > OFF wraps through zero", {}},
      {"equal_pair_full_turn", ParamKind::Boolean, d.equal_pair_full_turn, "ON == OFF always on", {}},
      {"reverse_advance", ParamKind::Text, std::string("signed"), "signed | disabled (R-ADV-6)",
       one_of({"signed", "disabled"})},
      {"fault_all_outputs",
       ParamKind::Boolean,
       d.fault_turns_off_all_outputs,
       "a transducer fault turns off all outputs (else the channel's)",
       {}},
      {"power_up_mask", ParamKind::Integer, static_cast<std::int64_t>(d.power_up_mask),
       "output mask at power-up", between(0.0, 255.0)},
      {"output_delay", ParamKind::Duration, d.output_delay, "update to output pin", between(0_us, 10_ms)},
      // A detection-power knob (docs/power.md): up to 100 ms either way, beyond every ON pulse
      // the shipped campaigns judge (one a turn, 62 .. 65 ms).
      {"output_off_skew", ParamKind::Duration, d.output_off_skew,
       "[KNOB] an output's turn-off delay minus its turn-on delay (0; one throughput, L253): > 0 "
       "stretches every ON pulse at the pin, < 0 shortens it",
       between(-100_ms, 100_ms)},
      {"input_delay", ParamKind::Duration, d.input_delay, "2742-18 input T_ON/T_OFF", between(0_us, 3_ms)},
      {"update_phase_from_seed",
       ParamKind::Boolean,
       true,
       "the first update falls at the seed's phase within one update period (else at 0)",
       {}},
      {"program_switch", ParamKind::Text, std::string(d.program_switch_at_program ? "program" : "display"),
       "where the front panel's Program switch stands at the start (L543; [[panel]] moves it)",
       one_of({"program", "display"})},
      {"program_jumper",
       ParamKind::Boolean,
       d.program_jumper_fitted,
       "the jumper next to the Program switch fitted; removed, the module is locked in Display Mode (L545)",
       {}},
      {"advance_speed_window", ParamKind::Duration, d.advance_speed_window,
       "the advances' speed is the motion over this moving window (R-ADV-5)", between(1_ms, 10_s)},
  };
  // The model's own rules across its settings (params_check.hpp): the reference against the
  // module's update period, the fault band's ends.
  info.conflict = [](const DutParams& params) -> std::optional<ParamConflict> {
    const auto found = p::params_conflict(pls2700_model(params), pls2700_params(params));
    if (!found) return std::nullopt;
    return ParamConflict{std::vector<std::string>(found->fields.begin(), found->fields.end()),
                         found->expected};
  };
  for (const auto& f : p::kFaultNames)
    info.variants.push_back({std::string(f.name), std::string(f.description)});
  // Transducer faults on the channel the campaign's [resolver] drives; the module detects them
  // from the signal (stator amplitude against the reference outside min_stator_ratio ..
  // max_stator_ratio, [X]) at its next reference peak.
  const std::string reaction =
      ": Err1 transducer fault (L601, L753, L765-772): that channel's position and tach words 8000h "
      "(L1315), limit outputs off (L1437; all 8 with fault_all_outputs), host programming ignored "
      "with 24h (L1763); latched until Clear Errors 8400h once the signal is back (L601, L1359); "
      "`until`: the signal is back";
  info.panel = {
      {"program_mode",
       "the Program switch pushed toward the back: Program Mode, PRG LED on (L543), unless the "
       "jumper is removed (L545) or the host disabled the keyboard (8100h, L543, L1356)"},
      {"display_mode", "the Program switch pushed toward the front: Display Mode, the keyboard cannot modify "
                       "parameters nor reset the position (L535)"},
      {"autozero_1", "CLEAR while channel 1's position is displayed: in Program Mode the module stores the "
                     "Circular Offset that makes the position 0 (AutoZero, L368); ignored in Display Mode "
                     "(L535) and while the channel's transducer fault is latched"},
      {"autozero_2", "the same for channel 2 (2732, 2742 and 2742-18 only; ignored on a one-channel module)"},
  };
  for (int out = 1; out <= p::kOutputCount; ++out)
    info.panel.push_back(
        {"delete_last_pair_" + std::to_string(out),
         "CLEAR on output " + std::to_string(out) +
             "'s last ON/OFF pair in Program Mode deletes it (L1078); where it overlapped another pair "
             "the output stays OFF over it until that pair is entered again or power is cycled (L1074); "
             "ignored in Display Mode (L535)"});
  info.power_cycle =
      "nvRAM keeps every parameter (L322, L776): setpoint pairs, advances, Scale Factor, Circular "
      "Offset, tach response, the keyboard lock (L1357); the resolver is absolute, so the position is "
      "the same after power-up. Back on, the setpoint tables are rebuilt from the stored pairs: an OFF "
      "space a deleted overlapping pair left is gone (L1058, L1074). [MODEL] lost: the programming "
      "error byte, a latched transducer fault (detected again if still there), the output mask (FFh, "
      "power_up_mask, R-M-2), the tach value and 2742-18 cycles (they start again); while off: outputs "
      "off, no updates, every host word reads 0 and block transfers are ignored; no power-up delay";
  info.faults = {
      {"transducer_loss", "the resolver lost (cable off: both stators at amplitude 0)" + reaction,
       FaultSite::OpenStators, true},
      {"open_sin_coil",
       "the SIN stator line open (amplitude 0), detected where COS alone is too small" + reaction,
       FaultSite::OpenSin, true},
      {"open_cos_coil",
       "the COS stator line open (amplitude 0), detected where SIN alone is too small" + reaction,
       FaultSite::OpenCos, true},
  };
  info.host =
      HostInterface{p::kMaxBtwWords + 1, kPls2700SingleTransferWord + 1, false, 15, 15, p::kMaxBtwWords};
  // A one-channel module's BTR is 3 words, a two-channel one's 5 (L1260); only the 2731-04
  // has the single-transfer word (L433, L1318; not the 2732-04, L437).
  info.host.input_absent = [](const DutParams& params, std::size_t word) -> std::string {
    const p::ModelTraits& model = p::traits(pls2700_model(params));
    if (word == kPls2700SingleTransferWord && !model.single_transfer)
      return fmt::format(
          "no input word {} on the {}: the single-transfer position word is the 2731-04's only "
          "(L433, L1318)",
          word, model.name);
    if (word < kPls2700ErrorWord && word >= static_cast<std::size_t>(model.btr_words))
      return fmt::format("no input word {} on the {}: its block transfer read is words 0 .. {} (L1260)", word,
                         model.name, model.btr_words - 1);
    return {};
  };
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    const auto fault = p::fault_from_name(variant);
    if (!fault) throw std::invalid_argument("pls2700 has no variant " + std::string(variant));
    const p::ModelVariant model = pls2700_model(params);
    p::Params q = pls2700_params(params);
    if (params.boolean("update_phase_from_seed"))
      q.update_phase = phase_from_seed(seed, p::traits(model).update_period);
    return std::make_unique<Pls2700Dut>(scheduler, model, q, *fault);
  };
  return info;
}

} // namespace hilrig::duts
