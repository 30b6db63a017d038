#include "rig/duts/amci4501_dut.hpp"
#include "rig/duts/seed_phase.hpp"

#include <array>
#include <memory>
#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/amci4501/amci4501.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace m = hilrig::models::amci4501;

// Pin names, in the order of Pins' fields.
constexpr std::array<const char*, 6> kPinNames{"A", "B", "Z", "START", "LATCH", "CYCLE_OUT"};

class Amci4501Dut final : public Dut {
public:
  Amci4501Dut(Scheduler& scheduler, const m::Params& params) : scheduler_(scheduler), params_(params) {}

  // Unwired inputs get a private idle line ("amci4501.<pin>"); Z stays unconnected.
  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    std::array<std::string, kPinNames.size()> lines;
    for (std::size_t i = 0; i < kPinNames.size(); ++i) lines[i] = std::string("amci4501.") + kPinNames[i];
    bool z_wired = false;
    for (const auto& [pin, line] : pin_to_line) {
      std::size_t i = 0;
      while (i < kPinNames.size() && pin != kPinNames[i]) ++i;
      if (i == kPinNames.size()) throw std::invalid_argument("amci4501 has no pin " + pin);
      lines[i] = line;
      if (i == 2) z_wired = true;
    }
    const m::Pins pins{bus.line(lines[0]).reader(), bus.line(lines[1]).reader(),
                       bus.line(lines[3]).reader(), bus.line(lines[4]).reader(),
                       bus.line(lines[5]).driver(), z_wired ? &bus.line(lines[2]).reader() : nullptr};
    module_ = std::make_unique<m::Amci4501>(scheduler_, pins, params_);
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    if (!module_) throw std::logic_error("amci4501: host write before attach");
    module_->write_output(word, value);
  }
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    if (!module_) throw std::logic_error("amci4501: host read before attach");
    return module_->input_words().at(word);
  }
  void power(bool on) override {
    if (!module_) throw std::logic_error("amci4501: power cycle before attach");
    if (on)
      module_->power_on();
    else
      module_->power_off();
  }

private:
  Scheduler& scheduler_;
  m::Params params_;
  std::unique_ptr<m::Amci4501> module_;
};

m::Jumper jumper(const std::string& text, const char* which) {
  if (text == "rising") return m::Jumper::Rising;
  if (text == "falling") return m::Jumper::Falling;
  throw std::invalid_argument(std::string("amci4501 ") + which + " is rising or falling, not " + text);
}

} // namespace

m::Params amci4501_params(const DutParams& params) {
  m::Params p;
  p.throughput = params.duration("throughput");
  p.mode5_throughput = params.duration("mode5_throughput");
  p.late_throughput = params.duration("late_throughput");
  p.output_off_skew = params.duration("output_off_skew");
  p.timer_resolution = params.duration("timer_resolution");
  p.velocity_window = params.duration("velocity_window");
  p.default_timeout = params.duration("default_timeout");
  p.cycle_output_on = params.text("cycle_output_on") == "low" ? Level::Low : Level::High;
  p.start_jumper = jumper(params.text("start_jumper"), "start_jumper");
  p.latch_jumper = jumper(params.text("latch_jumper"), "latch_jumper");
  p.no_response_missed = static_cast<unsigned>(params.integer("no_response_missed"));
  p.fw_version = static_cast<unsigned>(params.integer("fw_version"));
  p.mode4_timeout_sets_new = params.boolean("mode4_timeout_sets_new");
  p.z_resets_in_all_modes = params.boolean("z_resets_in_all_modes");
  p.lower_word_over_999_is_error = params.boolean("lower_word_over_999_is_error");
  p.saturate_latch_counts = params.boolean("saturate_latch_counts");
  p.acknowledge_on_rising_edge = params.boolean("acknowledge_on_rising_edge");
  p.acknowledge_invalid_program = params.boolean("acknowledge_invalid_program");
  p.program_clears_results = params.boolean("program_clears_results");
  return p;
}

DutInfo amci4501_info() {
  DutInfo info;
  info.name = "amci4501";
  info.description = "AMCI 4501 registration module, six modes (virtual model, docs/spec/amci4501.md)";
  info.pins = {
      {"A", PinDirection::Input, "encoder channel A (+A/-A, 5 V differential)", false},
      {"B", PinDirection::Input, "encoder channel B", false},
      {"Z", PinDirection::Input, "encoder index Z (resets the count in mode 2)", false},
      {"START", PinDirection::Input, "Start input (pin 6)", false},
      {"LATCH", PinDirection::Input, "Latch input (pin 7)", false},
      {"CYCLE_OUT", PinDirection::Output, "Cycle Output (pins 5/4), high while sinking", false},
  };
  const m::Params d{};
  // Ranges (docs/spec/amci4501.md): throughput 125 us (L281) or 100 us (L49), a model 0 .. 10 ms;
  // 1 us timer resolution (L26): 1 ns .. 1 ms; 50 ms velocity window (L114): 1 ms .. 10 s;
  // No Response after 4 (L88) or 5 (L223) missed cycles: 1 .. 100; firmware 1 .. 3 (v2 adds the
  // mode 4 filters, L36; v3 the timeout report, L95-L102).
  info.params = {
      {"throughput", ParamKind::Duration, d.throughput, "input edge to response (L281)",
       between(0_us, 10_ms)},
      {"mode5_throughput", ParamKind::Duration, d.mode5_throughput, "the same in mode 5 (L49, A1)",
       between(0_us, 10_ms)},
      {"late_throughput", ParamKind::Duration, d.late_throughput, "response delay of variant late_outputs",
       between(0_us, 10_ms)},
      // A detection-power knob (docs/power.md): up to 100 ms either way, beyond every Cycle
      // Output width the shipped campaigns judge (Start to Latch <= 43 ms).
      {"output_off_skew", ParamKind::Duration, d.output_off_skew,
       "[KNOB] the Cycle Output's turn-off delay minus its turn-on delay (0; one throughput, L281): > 0 "
       "stretches every pulse at the pin, < 0 shortens it",
       between(-100_ms, 100_ms)},
      {"timer_resolution", ParamKind::Duration, d.timer_resolution, "time measurement tick (L26)",
       between(1_ns, 1_ms)},
      {"velocity_window", ParamKind::Duration, d.velocity_window, "velocity counts per window (L114)",
       between(1_ms, 10_s)},
      {"default_timeout", ParamKind::Duration, d.default_timeout,
       "the timeout that timeout word 0 means (L169)", between(1_ms, 100_s)},
      {"cycle_output_on", ParamKind::Text, std::string("high"),
       "the Cycle Output line's level while the output sinks (L277)", one_of({"high", "low"})},
      {"start_jumper", ParamKind::Text, std::string("rising"), "JP6: rising (pins 1-2) or falling (3-4)",
       one_of({"rising", "falling"})},
      {"latch_jumper", ParamKind::Text, std::string("rising"), "JP5: rising (pins 1-2) or falling (3-4)",
       one_of({"rising", "falling"})},
      {"no_response_missed", ParamKind::Integer, std::int64_t{d.no_response_missed},
       "missed cycles before No Response (A4)", between(1.0, 100.0)},
      {"fw_version", ParamKind::Integer, std::int64_t{d.fw_version},
       "firmware: 2 = mode 4 filters, 3 = timeout report", between(1.0, 3.0)},
      {"mode4_timeout_sets_new",
       ParamKind::Boolean,
       d.mode4_timeout_sets_new,
       "bit 0 with the mode 4 timeout report",
       {}},
      {"z_resets_in_all_modes",
       ParamKind::Boolean,
       d.z_resets_in_all_modes,
       "Z zeroes the count outside mode 2",
       {}},
      {"lower_word_over_999_is_error",
       ParamKind::Boolean,
       d.lower_word_over_999_is_error,
       "setpoint lower word > 999 is a Parameter Error",
       {}},
      {"saturate_latch_counts",
       ParamKind::Boolean,
       d.saturate_latch_counts,
       "mode 2 L values cap at 32,767",
       {}},
      {"acknowledge_on_rising_edge",
       ParamKind::Boolean,
       d.acknowledge_on_rising_edge,
       "result acknowledge on control bit 0's rising edge (else any write with it set)",
       {}},
      {"acknowledge_invalid_program",
       ParamKind::Boolean,
       d.acknowledge_invalid_program,
       "an invalid programming cycle is still acknowledged",
       {}},
      {"program_clears_results",
       ParamKind::Boolean,
       d.program_clears_results,
       "a valid programming cycle clears the result words and aborts a running cycle (false: the manual, "
       "L167-L168)",
       {}},
  };
  for (const auto& v : m::kVariantNames)
    info.variants.push_back({std::string(v.name), std::string(v.description)});
  info.power_cycle =
      "no non-volatile memory: the module always powers up in mode 1 (L176, L255), the configuration, "
      "the count, the results and every status flag lost (status bits 8-12 all 0, L87-110); while off "
      "[MODEL]: Cycle Output off, inputs not seen, input words 0, host writes kept but acted on only "
      "from the next edge after power-up";
  info.host = HostInterface{m::kWords, m::kWords, true, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    m::Params p = amci4501_params(params);
    p.velocity_phase = phase_from_seed(seed, p.velocity_window);
    const auto v = m::variant_from_string(variant);
    if (!v) throw std::invalid_argument("amci4501 has no variant " + std::string(variant));
    p.variant = *v;
    return std::make_unique<Amci4501Dut>(scheduler, p);
  };
  return info;
}

} // namespace hilrig::duts
