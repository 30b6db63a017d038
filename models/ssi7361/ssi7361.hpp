#pragma once
// The virtual AMCI 7361 SSI interface module (docs/spec/ssi7361.md): the SSI master.
// A deterministic state machine on a hilrig::Scheduler. It drives the clock line (idle high;
// 25 falling and 25 rising edges per frame, F1 every TINT = 500/250 us at 125/500 kHz, so
// F25 to the next F1 is TIDL = 308/202 us), samples the data line half a period after each
// rising edge, and turns each 25-bit frame into the raw word, the Data Value and (every
// Rate Update Time) the Rate of Change. The PLC talks to it through 7 command words
// (%Q, %AQ1..6) and 7 status words (%I, %AI1..6), host_words.hpp; registers.hpp serves
// the same words as a core RegisterMap.
//
//   Scheduler s; virt::VirtualBus bus{s};
//   auto& clk = bus.line("ssi.clock", Level::High);
//   auto& data = bus.line("ssi.data", Level::High);      // undriven DATA reads 1 (L2178)
//   Ssi7361 module{s, clk.driver(), data.reader()};
//   module.write_command_words(1, aq);                   // %AQ1..6 first, TRMT = 0
//   module.write_command(cmd::kQ, qbit::kTransmit | qbit::kFormat);
//   s.run_until(t); auto w = module.status_words();     // ACK, errors, DV, RoC, raw
//
// The frames run for ever: drive the scheduler with run_until(), never run_until_idle().

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "models/ssi7361/host_words.hpp"
#include "models/ssi7361/params.hpp"
#include "models/ssi7361/programming.hpp"
#include "models/ssi7361/setup.hpp"
#include "signals/ssi_master.hpp"

namespace hilrig::models::ssi7361 {

class Ssi7361 {
public:
  // Starts the first frame at params.first_frame (not before now). Lines and scheduler
  // must outlive the module; it drives `clock` high at once.
  Ssi7361(Scheduler& scheduler, LineOutput& clock, LineInput& data, Params params = {});
  Ssi7361(const Ssi7361&) = delete;
  Ssi7361& operator=(const Ssi7361&) = delete;
  ~Ssi7361();

  // ---- host side (the PLC backplane) ----
  // Writes command words first.. (0 = %Q, 1..6 = %AQ1..6) as one transaction; a TRMT 0->1
  // edge in %Q starts a Programming Cycle on the words as they are after the write.
  // Throws std::out_of_range past word 6.
  void write_command_words(std::size_t first, std::span<const std::uint16_t> words);
  void write_command(std::size_t word, std::uint16_t value) { write_command_words(word, {&value, 1}); }
  // Reads status words first.. (0 = %I, 1..6 = %AI1..6). Throws std::out_of_range past 6.
  void read_status_words(std::size_t first, std::span<std::uint16_t> out) const;
  [[nodiscard]] StatusWords status_words() const;
  [[nodiscard]] const CommandWords& command_words() const { return commands_; }

  // ---- the rig's side of the connector ----
  // The external +24 V on pins 1/2: without it the opto inputs read every bit as 1.
  void set_sensor_supply(bool on) { supply_ = on; }
  // Fault injection: an EEPROM parameter checksum fails (E2Err, %I bit 13).
  void corrupt_eeprom() { state_.errors |= ibit::kEepromError; }

  // ---- the supply (a power cycle of the rack) ----
  // Off: no frames, no programming cycles, every status word 0 [MODEL]; the clock stops at
  // its idle level, high [MODEL: an unpowered line driver leaves the receiver's fail-safe
  // idle]. What is in EEPROM survives: the setup and LO (L1304-1306). On: as at power-up —
  // every error cleared (L254-256, L921-923) except E2Err, whose corrupted parameter is still
  // in EEPROM [MODEL]; no frame, no rate yet; the first frame after first_frame (+ phase).
  void power_off();
  void power_on();
  [[nodiscard]] bool powered() const { return powered_; }

  // ---- state, for reports and tests ----
  [[nodiscard]] std::uint32_t raw() const { return raw_; }
  [[nodiscard]] std::int32_t data_value() const;
  [[nodiscard]] std::int32_t rate() const { return rate_; }
  [[nodiscard]] const Setup& setup() const { return state_.setup; }
  [[nodiscard]] std::int64_t offset() const { return state_.offset; }
  [[nodiscard]] bool acknowledge() const { return ack_; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t eeprom_writes() const { return state_.eeprom_writes; }
  [[nodiscard]] const Params& params() const { return params_; }
  [[nodiscard]] const signals::SsiMaster& master(bool clock_500khz) const {
    return masters_[clock_500khz ? 1 : 0];
  }

private:
  enum class StepKind : std::uint8_t { Fall, Rise, Sample };
  struct Step {
    Nanos offset; // from F1
    StepKind kind;
  };
  static constexpr std::size_t kFrameBits = 25;
  using FrameSteps = std::array<Step, 3 * kFrameBits>;

  [[nodiscard]] FrameSteps build_steps(const signals::SsiMaster& master) const;
  void start_frame(Nanos at);
  void on_step();
  void finish_frame();
  void on_rate_update();
  void restart_rate_window();
  void on_transmit_rise();
  void on_transmit_fall();
  void run_programming_cycle();
  void recompute();
  void cancel_events();

  Scheduler& scheduler_;
  LineOutput& clock_;
  LineInput& data_;
  Params params_;
  std::array<signals::SsiMaster, 2> masters_;
  std::array<FrameSteps, 2> steps_{};

  // SSI master
  std::size_t frame_clock_ = 0; // 0 = 125 kHz, 1 = 500 kHz: latched at F1
  Nanos frame_start_{0};
  std::size_t step_ = 0;
  std::uint32_t shift_ = 0;
  EventId frame_event_{};
  bool supply_ = true;
  bool powered_ = true;

  // data and rate
  std::uint32_t raw_ = 0; // until the first frame completes
  std::int64_t dv_ = 0;
  std::int64_t dv_at_window_ = 0;
  std::uint64_t frames_at_window_ = 0; // frames read when the rate window started
  std::int32_t rate_ = 0;
  bool rate_overflow_ = false;
  EventId rate_event_{};
  std::uint64_t frames_ = 0;

  // host
  CommandWords commands_{};
  CommandWords latched_{};
  bool transmit_ = false;
  bool ack_ = false;
  EventId cycle_event_{};   // a cycle waiting for acknowledge_delay
  EventId release_event_{}; // ACK dropping acknowledge_delay after TRMT fell
  ProgramState state_{};
};

} // namespace hilrig::models::ssi7361
