#pragma once
// One limit-switch output's logic (spec §4.3-§4.9): its position, setpoint pairs with
// advances, timed limit and enabling conditions, evaluated once per scan.
// final = calc_adv & timer_ok & en_rpm & en_simple & en_pulse & en_window & en_sr.
#include <cstdint>
#include <optional>

#include "core/time.hpp"
#include "models/ans1/advance.hpp"
#include "models/ans1/enable.hpp"
#include "models/ans1/output_setup.hpp"
#include "models/ans1/quiet_interval.hpp"
#include "models/ans1/setpoint.hpp"
#include "models/ans1/timed_limit.hpp"

namespace hilrig::models::ans1 {

class ShiftRegister;

// What a scan knows that every output shares.
struct ScanState {
  Nanos now{};
  std::uint16_t gmp = 0;
  std::uint16_t fsc = 360;
  double speed = 0.0;              // S, signed machine cycles per minute
  std::int16_t speed_reported = 0; // S as DA16 w2 shows it
  std::uint16_t active_inputs = 0; // logical input states, bit n-1 = input n
  const ShiftRegister* shift_register = nullptr;
  bool shift_register_enabled = false;
  // Fault variants.
  bool advance_wrong_sign = false;
  bool late_wrap_to = false;
  Nanos timer_error{0}; // Params::timer_error: added to every timed output's time
};

// Each condition as DA16 words 10..16 show it (1 = not blocking).
struct OutputState {
  bool calc = false;    // pairs with advances, before timer and enabling (w10)
  bool simple = true;   // w11
  bool pulse = true;    // w12
  bool window = true;   // w13
  bool sr = true;       // w14
  bool rpm = true;      // w15
  bool timer_ok = true; // w16
  bool ls = false;      // the output's LS function
  friend bool operator==(const OutputState&, const OutputState&) = default;
};

class OutputChannel {
public:
  void configure(const OutputSetup& setup);
  [[nodiscard]] const OutputSetup& setup() const { return setup_; }
  // Recomputes the advance counts for a new speed (every speed update and on programming).
  void update_advances(double speed, std::uint16_t fsc, double scale);
  [[nodiscard]] const AdvanceCounts& advances() const { return advances_; }

  [[nodiscard]] std::uint16_t ls_position(std::uint16_t gmp, std::uint16_t fsc) const;
  // LS preset (§4.3): LSO = LSPV - GMP, with the value first replaced when given.
  void preset(std::uint16_t gmp, std::optional<std::uint16_t> value = std::nullopt);
  void set_offset(std::int32_t offset) { setup_.ls_offset = offset; }

  OutputState scan(const ScanState& scan, bool retrigger_restarts);
  [[nodiscard]] const OutputState& state() const { return state_; }
  // Exact scan skipping while the encoder moves: narrows `quiet` to the GMP values around
  // scan.gmp at which every position condition of scan() (each pair's on-state with its
  // advanced edges, the window, a Time-Only hold) keeps its value at scan.gmp.
  void keep_quiet(QuietInterval& quiet, const ScanState& scan) const;
  // The earliest time at which scan() with the same inputs can give another state (its timer).
  [[nodiscard]] Nanos next_change() const { return timer_.expiry(); }
  // The inputs scan() reads (bit n-1 = input n): its simple, pulse and window ANDing.
  [[nodiscard]] std::uint16_t inputs_read() const {
    const auto window =
        window_input_ >= 0 ? static_cast<std::uint16_t>(1U << static_cast<unsigned>(window_input_)) : 0U;
    return static_cast<std::uint16_t>(simple_inputs_ | pulse_inputs_ | window);
  }

private:
  [[nodiscard]] EdgeShift edge_shift(const ScanState& scan) const;

  OutputSetup setup_{};
  AdvanceCounts advances_{};
  TimedLimit timer_{};
  PulseLatch pulse_{};
  WindowLatch window_{};
  OutputState state_{};
  std::uint16_t simple_inputs_ = 0;
  std::uint16_t pulse_inputs_ = 0;
  int window_input_ = -1;
  friend bool operator==(const OutputChannel&, const OutputChannel&) = default;
};

} // namespace hilrig::models::ans1
