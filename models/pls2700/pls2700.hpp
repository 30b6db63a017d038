#pragma once
// The virtual AMCI Series 2700 programmable limit switch (docs/spec/pls2700.md), any of the seven
// modules. A deterministic state machine on a Scheduler with the module's own update
// period (200 us one channel, 400 us two channels, L377/L457): at each update it samples the
// stator channels at the latest peak of its own reference, decodes 8,192 counts per turn,
// applies Scale Factor and Circular Offset, runs the tachometer, the 2742-18 cycle logic and
// the limit windows with advances, and drives the eight outputs.
//
// On the virtual bus:
//   virt::VirtualBus bus(scheduler);
//   Pls2700 pls(scheduler, wire_pins(bus, "pls."), ModelVariant::M2742);
//   signals::Resolver r(pls.excitation().resolver_params(), angle);   // carrier-synchronous
//   bus.analog("pls.SIN1").set_waveform(r.sin_waveform()); ...COS1 likewise
//   pls.write_btw(words);  pls.btr_word(0);                             // host words
#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <span>

#include "core/scheduler.hpp"
#include "core/skewed_output.hpp"
#include "models/pls2700/advance_speed.hpp"
#include "models/pls2700/cycle.hpp"
#include "models/pls2700/faults.hpp"
#include "models/pls2700/limits.hpp"
#include "models/pls2700/model_variant.hpp"
#include "models/pls2700/params.hpp"
#include "models/pls2700/pls2700_pins.hpp"
#include "models/pls2700/position.hpp"
#include "models/pls2700/setup.hpp"
#include "models/pls2700/tachometer.hpp"

namespace hilrig::models::pls2700 {

inline constexpr std::uint16_t kFaultWord = 0x8000; // position/tach word on a transducer fault
inline constexpr std::size_t kMaxBtwWords = 64;

class Pls2700 {
public:
  // Updates start at the first reference peak at or after scheduler.now() +
  // params.update_phase. Keep the device alive while
  // the scheduler runs. Throws std::invalid_argument on params that do not go together
  // (params_check.hpp).
  Pls2700(Scheduler& scheduler, ModelVariant model, const Params& params = {}, Fault fault = Fault::Nominal);
  Pls2700(Scheduler& scheduler, const Pls2700Pins& pins, ModelVariant model, const Params& params = {},
          Fault fault = Fault::Nominal);
  ~Pls2700();
  Pls2700(const Pls2700&) = delete;
  Pls2700& operator=(const Pls2700&) = delete;

  void attach(const Pls2700Pins& pins);

  // ---- Host (block transfers, §5) ----
  // One BTW of 1..64 words (§5.4). Returns the programming error byte afterwards.
  std::uint8_t write_btw(std::span<const std::uint16_t> words);
  // BTR words (3 or 5, §5.1): copies min(out.size(), btr_words) words; returns how many.
  std::size_t read_btr(std::span<std::uint16_t> out) const;
  // Word `index` (0-based) of the BTR; 0 beyond its length.
  [[nodiscard]] std::uint16_t btr_word(std::size_t index) const;
  [[nodiscard]] std::size_t btr_words() const { return static_cast<std::size_t>(model_.btr_words); }
  // 2731-04 single-transfer input word (§5.2); the same word on other models.
  [[nodiscard]] std::uint16_t single_transfer_word() const { return powered_ ? position_word(1) : 0; }
  [[nodiscard]] std::uint16_t position_word(int channel) const; // channel 1 or 2
  [[nodiscard]] std::uint16_t tach_word(int channel) const;
  [[nodiscard]] std::uint16_t status_word() const {
    return static_cast<std::uint16_t>((error_byte_ << 8) | output_states_);
  }
  [[nodiscard]] std::uint8_t error_byte() const { return powered_ ? error_byte_ : 0; }

  // ---- Front panel (keyboard in Program Mode); false outside Program Mode ----
  // The Program switch (L543): toward the back (true) = Program Mode, front = Display Mode.
  void set_program_switch(bool program) { switch_program_ = program; }
  [[nodiscard]] bool program_switch() const { return switch_program_; }
  // Program Mode, PRG LED on (L534): the switch at program, its jumper fitted (L545) and the
  // keyboard not disabled by the host's 8100h ("locked into display mode from the processor",
  // L543, L1356). The modes are the front panel's only (L537): the host's words act in either.
  [[nodiscard]] bool program_mode() const {
    return powered_ && switch_program_ && params_.program_jumper_fitted && !setup_.keyboard_disabled;
  }
  bool autozero(int channel); // R-CO-3: CLEAR while the position is displayed (L368, L534-535)
  // R-LS-7/R-LS-5: CLEAR on pair `pair` (1-based) of `output` deletes it; where another
  // pair overlapped it the output stays off (W8) until that pair is re-entered or power cycles.
  bool keyboard_delete_pair(int output, int pair);
  // The supply off / back on (README "Power cycle"). The nvRAM setup is kept (L322, L776): pairs,
  // advances, SF, offsets, tach codes, the keyboard lock (L1357). Back on, the position tables are
  // rebuilt from the stored pairs (L1074: an OFF space a deleted overlapping pair left is gone),
  // the position read afresh from the absolute resolver, errors and a latched transducer fault
  // cleared (re-detected if still there), the mask FFh (R-M-2), the tach and 2742-18 cycles
  // restarted. Off: outputs off, no updates, the host reads 0 and its writes are ignored.
  void power_off();
  void power_on();
  void power_cycle() {
    power_off();
    power_on();
  }
  [[nodiscard]] bool powered() const { return powered_; }

  // ---- State ----
  [[nodiscard]] int machine_position(int channel) const { return mp_[index(channel)]; }
  [[nodiscard]] int raw_position(int channel) const { return raw_[index(channel)]; } // 0..8191
  [[nodiscard]] std::uint16_t tach(int channel) const { return tach_[index(channel)].value(); }
  [[nodiscard]] bool transducer_fault(int channel) const { return fault_latched_[index(channel)]; }
  [[nodiscard]] std::uint8_t output_states() const { return output_states_; } // bit 0 = output 1
  [[nodiscard]] bool input_energized(int channel) const;                      // 2742-18
  [[nodiscard]] const CycleLogic& cycle(int channel) const { return cycles_[index(channel)]; }
  [[nodiscard]] int owner(int output) const; // channel 1 or 2
  [[nodiscard]] const Setup& setup() const { return setup_; }
  [[nodiscard]] const ModelTraits& model() const { return model_; }
  [[nodiscard]] Fault fault() const { return fault_; }
  [[nodiscard]] const Params& params() const { return params_; }
  [[nodiscard]] const Excitation& excitation() const { return excitation_; }
  [[nodiscard]] Nanos update_period() const { return period_; }
  [[nodiscard]] std::uint64_t updates() const { return updates_; }

private:
  struct InputEvent {
    Nanos time;
    Level level;
  };
  static constexpr std::size_t kInputQueue = 32;
  struct InputQueue {
    std::array<InputEvent, kInputQueue> events{};
    std::size_t head = 0;
    std::size_t count = 0;
    Level level = Level::Low; // energized, as the last edge left it
  };
  // Shared with the line handlers, which may outlive the device.
  using InputState = std::array<InputQueue, 2>;
  using OutputPins = std::array<LineOutput*, kOutputCount>;

  [[nodiscard]] static std::size_t index(int channel) { return static_cast<std::size_t>(channel - 1); }
  [[nodiscard]] int channels() const { return model_.channels; }
  void schedule_update(Nanos at);
  void update();
  void sample_channel(std::size_t ch, Nanos peak);
  void run_cycles(Nanos now);
  [[nodiscard]] std::uint8_t evaluate_outputs() const;
  void drive_outputs(std::uint8_t levels);
  void restart_tach(std::size_t ch);
  void clear_errors();
  void after_program(const Setup& before, int entered_output);
  [[nodiscard]] bool any_fault_latched() const;
  [[nodiscard]] double speed_counts_per_ms(std::size_t ch) const;

  Scheduler& scheduler_;
  const ModelTraits& model_;
  Params params_;
  bool switch_program_ = true; // the Program switch (from Params at construction)
  Fault fault_;
  Nanos period_;
  Excitation excitation_;
  Pls2700Pins pins_{};
  Setup setup_{};

  std::array<int, 2> raw_{};
  std::array<int, 2> mp_{};
  std::array<int, 2> raw_step_{}; // last update's motion, 8192 counts
  std::array<bool, 2> have_raw_{};
  std::array<bool, 2> fault_present_{};
  std::array<bool, 2> fault_latched_{};
  std::array<Tachometer, 2> tach_{};
  std::array<AdvanceSpeed, 2> advance_speed_;
  Nanos first_update_{0};
  Nanos last_update_{-1};
  std::array<CycleLogic, 2> cycles_{};
  std::shared_ptr<InputState> inputs_;
  std::shared_ptr<OutputPins> outputs_;
  // The output drivers outputs_ points at (kept alive by a pending delayed write too).
  std::shared_ptr<std::array<std::unique_ptr<SkewedOutput>, kOutputCount>> drivers_;
  std::array<HoleTable, kOutputCount> holes_{};
  std::uint8_t output_states_ = 0;
  std::uint8_t error_byte_ = 0;
  std::uint64_t updates_ = 0;
  bool powered_ = true;
  EventId update_event_{};
};

} // namespace hilrig::models::pls2700
