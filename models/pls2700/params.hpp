#pragma once
// Every [I]/[X] choice of the digest (pls2700.md) as a named parameter, with its default.
#include <cstdint>

#include "core/time.hpp"

namespace hilrig::models::pls2700 {

// R-ADV-6: how advances act while the position decreases.
enum class ReverseAdvance : std::uint8_t {
  Signed,   // option A: signed speed, windows shift toward the approaching side (default)
  Disabled, // option B: no advance while v < 0
};

struct Params {
  // Resolver reference on R1/R2 [X, §2.2]: amplitude * cos(2 pi f t), so a peak falls on every
  // multiple of 1/(2f) — with 5 kHz every 100 us, on the 200/400 us update grid. Only a
  // frequency whose peaks fall on that grid is taken (params_check.hpp).
  double excitation_hz = 5'000.0;
  double excitation_amplitude = 1.0;
  // Transducer fault threshold [X, §2.2]: demodulated stator/reference ratio outside this closed
  // band; min <= max (params_check.hpp).
  double min_stator_ratio = 0.5;
  double max_stator_ratio = 1.5;
  // Tach code 0 is 32 ms on single-channel modules (L469) instead of 30 ms (L374) [§7.2].
  bool tach_32ms_on_single_channel = false;
  // R-LS-3: a pair with ON > OFF wraps through zero on standard models.
  bool wrap_pairs = true;
  // R-LS-4: ON == OFF means "never on" (false) or "always on" (true).
  bool equal_pair_full_turn = false;
  ReverseAdvance reverse_advance = ReverseAdvance::Signed;
  // R-ADV-5 [X]: the advances' speed is the motion over this moving window (advance_speed.hpp);
  // 200 ms = twice the largest advance (99 ms, L1393) keeps every advanced edge within one count.
  Nanos advance_speed_window{200'000'000};
  // §4.9 / §7.20: a transducer fault switches off all eight outputs (true) or only the outputs
  // allocated to the faulted channel (false).
  bool fault_turns_off_all_outputs = true;
  // §4.10 front panel: the Program switch toward the back = Program Mode (L543) [the manual
  // gives no factory position; the model's keyboard acts, as it always did]; without the jumper
  // next to it the module is locked in Display Mode (L545).
  bool program_switch_at_program = true;
  bool program_jumper_fitted = true;
  // R-M-2: output mask at power-up.
  std::uint8_t power_up_mask = 0xFF;
  // Output driver delay d_drv and 2742-18 input delay (T_ON/T_OFF, max 3 ms, L1724) [X].
  Nanos output_delay{0};
  Nanos input_delay{0};
  // [MODEL] The manual gives one throughput for the outputs (200 / 400 us, L253, L455), so an
  // output turns off as fast as on. A detection-power knob (README, docs/power.md): a driver
  // that turns off this much slower (< 0: turns on slower) than on stretches (shortens) every
  // ON pulse at the pin by it.
  Nanos output_off_skew{0};
  // First update tick relative to construction, moved on to the next reference peak (the
  // update clock is locked to the reference). A real board's phase is arbitrary: the rig
  // (rig/duts/pls2700_dut.cpp) draws it from the run's seed.
  Nanos update_phase{0};
};

} // namespace hilrig::models::pls2700
