#pragma once
// The virtual AMCI 4501 registration module (docs/spec/amci4501.md): a deterministic
// state machine on a hilrig::Scheduler. It decodes the encoder's A/B (X4, L7), watches the
// Start and Latch inputs through their polarity jumpers (L237), drives the Cycle Output
// (modes 1 and 2, L277) and keeps the SLC I/O image: 8 output words the host writes and 8
// input words it reads (host_words.hpp; registers.hpp serves them as a RegisterMap).
//
// Timing: captures (counts, timer ticks) are taken at the input edge; times count a 1 us
// timer (L26); every response to an input edge (Cycle Output edge, result words, Start/
// Latch Mark) appears Params::throughput (125 us, L281; 100 us in mode 5, L49) later.
// Host writes act at once (L167). Timeouts fire at the start edge + timeout.
// At one instant (README, "Same-instant order"): encoder/Z edges, then Start/Latch edges,
// then the timeout if the cycle has not ended, then the responses due then.
//
//   Scheduler s; virt::VirtualBus bus{s};
//   Amci4501 m{s, {bus.line("a").reader(), bus.line("b").reader(), bus.line("start").reader(),
//                  bus.line("latch").reader(), bus.line("cycle").driver()}};
//   m.write_output_words(0, words);   // O:s.0..7; Transmit (bit 15) 0->1 programs
//   s.run_until(t); m.input_words();  // I:s.0..7
//
// The velocity timer runs for ever: drive the scheduler with run_until(), not run_until_idle().

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "core/skewed_output.hpp"
#include "models/amci4501/host_words.hpp"
#include "models/amci4501/params.hpp"
#include "models/amci4501/programming.hpp"
#include "signals/quadrature_decoder.hpp"

namespace hilrig::models::amci4501 {

// The module's connector (L181-198) as the rig wires it.
struct Pins {
  LineInput& a;
  LineInput& b;
  LineInput& start;         // pin 6
  LineInput& latch;         // pin 7
  LineOutput& cycle_output; // pins 5/4
  LineInput* z = nullptr;   // pins 16/17, optional (mode 2 only, L12)
};

class Amci4501 {
public:
  // Lines and scheduler must outlive the module. Powers up in mode 1 (L176), input words 0.
  Amci4501(Scheduler& scheduler, const Pins& pins, Params params = {});
  Amci4501(const Amci4501&) = delete;
  Amci4501& operator=(const Amci4501&) = delete;

  // ---- host side (the SLC backplane) ----
  // Writes output words first.. as one transaction (throws std::out_of_range past word 7).
  // Control bit 0 going 0->1 acknowledges the result, bit 1 clears No Response and Time
  // Out, Transmit 0->1 starts a programming cycle on the words as written, 1->0 ends it.
  void write_output_words(std::size_t first, std::span<const std::uint16_t> words);
  void write_output(std::size_t word, std::uint16_t value) { write_output_words(word, {&value, 1}); }
  // Reads input words first.. (throws std::out_of_range past word 7).
  void read_input_words(std::size_t first, std::span<std::uint16_t> out) const;
  [[nodiscard]] InputWords input_words() const;
  [[nodiscard]] std::uint16_t status() const;
  [[nodiscard]] const OutputWords& output_words() const { return outputs_; }

  // ---- the supply (a power cycle of the chassis) ----
  // The module has no non-volatile memory and always powers up in mode 1 (L176, L255): off
  // forgets the configuration, the count, the results and every flag. While off [MODEL]: the
  // Cycle Output does not conduct (off), inputs are not seen, input words read 0, output words
  // the host writes are kept but act only from the next edge after power-up. On: as at
  // power-up (the constructor), the Start and Latch Marks from the inputs' levels then.
  void power_off();
  void power_on();
  [[nodiscard]] bool powered() const { return powered_; }

  // ---- state, for reports and tests ----
  [[nodiscard]] int mode() const { return config_.mode; }
  [[nodiscard]] const Config& config() const { return config_; }
  [[nodiscard]] std::int64_t position() const { return decoder_.count(); }
  [[nodiscard]] bool cycle_output_on() const { return cycle_output_on_; }
  [[nodiscard]] bool window_open() const { return window_; } // mode 2 enable window (REG LED)
  [[nodiscard]] std::uint64_t results_published() const { return published_; }
  [[nodiscard]] std::uint64_t results_missed() const { return missed_total_; }
  [[nodiscard]] std::uint64_t count_overflows() const { return overflows_; } // A11, A12, A24
  [[nodiscard]] std::uint64_t illegal_transitions() const { return decoder_.illegal_transitions(); }
  [[nodiscard]] Nanos response_delay() const; // the throughput in force now
  [[nodiscard]] const Params& params() const { return params_; }

private:
  enum class Phase : std::uint8_t { Idle, Running, WaitL1, WaitL2, WaitS2 };
  enum class Op : std::uint8_t { CycleOutput, Publish, Write, StartMark, LatchMark };
  struct Deferred {
    Nanos due;
    std::uint32_t generation;
    Op op;
    bool on;
    std::uint8_t first; // Publish/Write: first input word
    std::uint8_t count;
    std::array<std::uint16_t, 4> words;
  };

  // inputs
  void on_encoder(const Edge& e);
  void on_index(const Edge& e);
  void on_start(const Edge& e);
  void on_latch(const Edge& e);
  void take_start(Level level, Nanos t);
  void take_latch(Level level, Nanos t);
  void end_instant_later();
  void end_of_instant();
  [[nodiscard]] bool active(Level level, Jumper jumper) const;
  [[nodiscard]] std::int64_t tick(Nanos t) const { return t.count() / params_.timer_resolution.count(); }
  [[nodiscard]] std::uint64_t time_value(std::int64_t from, std::int64_t to) const;

  // mode rules (measure.cpp)
  void start_edge(bool now_active, Nanos t);
  void latch_edge(bool now_active, Nanos t);
  void mode2_position(int delta, Nanos t);
  void open_window(Nanos t);
  void close_window(Nanos t);
  void mode4_start(Nanos t);
  void mode4_latch(Nanos t);
  void on_timeout();
  [[nodiscard]] std::uint16_t latch_count();
  [[nodiscard]] std::uint16_t mode6_count(std::int64_t c);

  // responses
  void arm_timeout(Nanos from);
  void cancel_timeout();
  void defer(Nanos t, Op op, bool on = false, std::uint8_t first = 0,
             std::span<const std::uint16_t> words = {});
  void fire();
  void apply_due();
  void apply(const Deferred& d);
  void publish(std::span<const std::uint16_t> words, std::uint8_t first);
  void set_cycle_output(bool on);
  void end_cycle_output();
  void on_velocity_window(std::uint32_t epoch);

  // host
  void program();
  void reset_measurement();

  Scheduler& scheduler_;
  Pins pins_;
  Params params_;
  SkewedOutput cycle_driver_; // the Cycle Output's driver, on pins_.cycle_output
  bool powered_ = true;
  signals::QuadratureDecoder decoder_;
  Config config_{};
  std::uint32_t generation_ = 0; // bumped by each valid programming cycle

  OutputWords outputs_{};
  InputWords inputs_{}; // word 0 unused: status() composes it
  bool new_value_ = false;
  bool no_response_ = false;
  bool start_mark_ = false;
  bool latch_mark_ = false;
  bool command_error_ = false;
  bool parameter_error_ = false;
  bool timeout_error_ = false;
  bool acknowledge_ = false;
  unsigned missed_ = 0;

  // measurement state, as of the input edges (responses lag by the throughput)
  bool start_active_ = false;
  bool latch_active_ = false;
  bool cycle_output_on_ = false;
  Phase phase_ = Phase::Idle;
  std::int64_t p_start_ = 0;   // mode 1
  std::int64_t t_start_ = 0;   // modes 3, 4 (S1)
  std::int64_t t_l1_ = 0;      // mode 4
  std::int64_t tm1_ticks_ = 0; // mode 4
  std::int64_t t_l2_ = 0;      // mode 4
  bool have_s2_ = false;       // mode 4 Filter 2 reference
  std::int64_t t_s2_ = 0;
  std::int64_t tm2_ticks_ = 0;
  bool window_ = false; // mode 2
  bool in_pulse_ = false;
  int pulses_ = 0;
  std::array<std::uint16_t, 4> l_values_{};
  std::array<bool, 2> seen_active_{}; // modes 5, 6: [0] Start, [1] Latch
  std::array<std::int64_t, 2> on_tick_{};
  std::array<std::int64_t, 2> on_position_{};
  EventId timeout_event_{};
  Nanos timeout_due_{0}; // when timeout_event_ fires
  std::int64_t velocity_ref_ = 0;
  std::uint32_t velocity_epoch_ = 0; // bumped at power-up: the timer chain before it stops

  // Start/Latch edges of the current instant, taken at its end (end_of_instant()).
  struct InputEdge {
    bool start;
    Level level;
  };
  std::vector<InputEdge> instant_inputs_;
  EventId instant_end_event_{};

  std::vector<Deferred> deferred_;
  std::uint64_t published_ = 0;
  std::uint64_t missed_total_ = 0;
  std::uint64_t overflows_ = 0;
};

} // namespace hilrig::models::amci4501
