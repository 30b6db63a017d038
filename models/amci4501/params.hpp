#pragma once
// Parameters of the virtual AMCI 4501: every choice the manual leaves open (the digest's
// [I] / [MODEL] marks, docs/spec/amci4501.md) is a named field here with the digest's
// default, so a campaign can switch it.

#include <cstdint>

#include "core/line.hpp"
#include "core/time.hpp"
#include "models/amci4501/variants.hpp"

namespace hilrig::models::amci4501 {

// Polarity jumpers JP6 (Start) and JP5 (Latch), L237: pins 1-2 act on the rising
// transition, pins 3-4 on the falling one. "Active" is the level after that edge (A34).
enum class Jumper : std::uint8_t { Rising, Falling };

struct Params {
  // Throughput time (L281): the delay from an input edge to the module's response (Cycle
  // Output edge, result words, Start/Latch Mark). Reading (a) of A2; the examples accept
  // any response in [t, t + 125 us], so the default sits at the worst case.
  Nanos throughput = microseconds(125);
  // The same in mode 5, whose text quotes 100 us (L49 vs L281, A1).
  Nanos mode5_throughput = microseconds(100);
  // Response delay used by the "late_outputs" variant (beyond spec).
  Nanos late_throughput = microseconds(250);
  // [MODEL] The manual gives one throughput for every response (L281), so the Cycle Output
  // (an open collector sinking up to 20 mA, L277) turns off as fast as on. A detection-power
  // knob (README, docs/power.md): a driver that turns off this much slower (< 0: turns on
  // slower) than on stretches (shortens) every Cycle Output pulse at the pin by it.
  Nanos output_off_skew{0};
  // Time measurements count a free-running timer of this resolution (L26, L32, L49).
  Nanos timer_resolution = microseconds(1);
  // Velocity words: counts per window, refreshed every window (L114).
  Nanos velocity_window = milliseconds(50);
  // [MODEL] Where the first velocity window ends after power-up, in (0, velocity_window]:
  // velocity_window - velocity_phase. The rig draws the phase from the run's seed.
  Nanos velocity_phase{0};
  // Timeout word 0 means this (L169).
  Nanos default_timeout = seconds(10);

  Jumper start_jumper = Jumper::Rising; // JP6
  Jumper latch_jumper = Jumper::Rising; // JP5
  // Cycle Output ON (sinking, conducting, L277) as a level on the rig's line.
  Level cycle_output_on = Level::High;

  // No Response (status bit 1) after this many missed cycles following a reported one:
  // 4 per L88, 5 per L223 (A4).
  unsigned no_response_missed = 4;
  // Firmware version (A19): >= 2 has the mode 4 filters (L36), >= 3 reports mode 4
  // values on timeout (L95-102).
  unsigned fw_version = 3;
  // Mode 4 timeout report: whether New Measurement (bit 0) is set with it (A20, not stated).
  bool mode4_timeout_sets_new = false;
  // Z resets the position on its rising edge in mode 2 (L12); in the other modes [I] Z is
  // ignored unless this is set.
  bool z_resets_in_all_modes = false;
  // Mode 2: a setpoint lower word above 999 is a Parameter Error (not stated; A5).
  bool lower_word_over_999_is_error = true;
  // Mode 2: L1..L4 are capped at 32,767 (L115) rather than wrapped (not stated, A12).
  bool saturate_latch_counts = true;
  // Result acknowledge (A10): control bit 0's 0->1 edge (true), or any host write with bit
  // 0 set (false: a host that keeps writing the bit high acknowledges every result).
  bool acknowledge_on_rising_edge = true;
  // An invalid programming cycle is still acknowledged (A30, not stated).
  bool acknowledge_invalid_program = true;
  // [MODEL] off (the manual, L167-L168: bits 0 and 1 act at once, a programming cycle only
  // loads bits 2-6 and words 1-5): a same-mode programming cycle keeps the results and a
  // running cycle. On: every valid programming cycle clears the result words, bit 0 and
  // responses not yet out, and aborts a running cycle (an acknowledge sent with Transmit
  // then wipes the last measurement).
  bool program_clears_results = false;

  Variant variant = Variant::Correct;
};

} // namespace hilrig::models::amci4501
