#pragma once
// Every [MODEL] choice of the 7361 digest (docs/spec/ssi7361.md) where the manual is
// silent, as a named parameter with the digest's default. README.md lists them with the
// digest's reasons.

#include <cstdint>

#include "core/time.hpp"
#include "models/ssi7361/variants.hpp"

namespace hilrig::models::ssi7361 {

enum class RateRounding : std::uint8_t {
  Truncate, // Δ*1000/RUT truncated toward zero (digest §3, A9)
  Nearest,  // rounded half away from zero: the manual's "42" for 1000/24 (L2592)
};

enum class FormatClearsOffset : std::uint8_t {
  WhenSetupChanges, // LO cleared only if the Format command changes the SSI setup (A27)
  Always,           // literal L1235-1236: every Format command clears LO
};

enum class SampleInstant : std::uint8_t {
  HalfPeriodAfterRising, // bit k at k*T after F1, half a period after R_k (§2.1)
  AtRisingEdge,          // bit k at R_k itself (for a transducer faster than the line)
};

struct Params {
  // ---- SSI master (§2.1) ----
  Nanos first_frame = Nanos{0}; // F1 of the first frame after construction
  // [MODEL] The frame clock's power-up phase, added to first_frame: the rig draws it from
  // the run's seed, in [0, frame period at 125 kHz), unless the campaign pins first_frame.
  Nanos frame_phase{0};
  // Detection-power knobs (README, docs/power.md): a clock or frame timer off the manual's
  // figures by this much, added to the clock period T (8 / 2 us, L1123) and to the frame period
  // TINT (500 / 250 us, L1090, L1096). 0 = the manual's timing.
  Nanos clock_period_error{0};
  Nanos frame_period_error{0};
  SampleInstant sample_instant = SampleInstant::HalfPeriodAfterRising;
  bool read_all_ones_without_supply = true; // no +24 V on pins 1/2: every bit reads 1 (L2182-2184)

  // ---- data path (§2.3) ----
  bool invert_before_gray = true;    // Data Logic inversion before Gray decoding (A14)
  bool count_direction_wrap = false; // Negative direction maps field 0 to 0 instead of 2^N (A12)

  // ---- rate of change (§3) ----
  RateRounding rate_rounding = RateRounding::Truncate;
  std::int64_t rate_overflow_limit = 64'108'863; // ROVErr when |RoC| exceeds it (A3)
  bool preset_restarts_rate_window = false;      // an applied preset gives a one-window spike (§3)

  // ---- programming (§3, §5.4) ----
  FormatClearsOffset format_clears_offset = FormatClearsOffset::WhenSetupChanges;
  std::int32_t preset_limit = 33'554'431;   // |Preset| above it is PSTErr (A2)
  bool multiplier_may_equal_divisor = true; // MUL <= DIV (A4); false: MUL <= DIV - 1 (L2165)
  Nanos acknowledge_delay = Nanos{0};       // TRMT 0->1 (and 1->0) to ACK; 0 = in the same write

  Variant variant = Variant::Correct;
};

} // namespace hilrig::models::ssi7361
