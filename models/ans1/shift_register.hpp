#pragma once
// The 256-bit shift register (spec §4.9). While GMP is in the sensing window [From, To) an
// active SR input sets the capture bit; when GMP reaches the Shift Position moving forward
// the register shifts up (b[256] is lost) and b[1] takes the capture ([MODEL] for A4: the
// host's numbering 1..256). Reverse motion does not shift ([MODEL], not stated).
#include <array>
#include <bitset>
#include <cstdint>

#include "models/ans1/output_setup.hpp"
#include "models/ans1/quiet_interval.hpp"

namespace hilrig::models::ans1 {

// True when moving forward from `from` to `to` (a step shorter than half a cycle) passes
// through or lands on `mark`. Landing on `from` itself is not a crossing.
[[nodiscard]] bool crossed_forward(std::uint16_t from, std::uint16_t to, std::uint16_t mark,
                                   std::uint16_t fsc);

class ShiftRegister {
public:
  void step(std::uint16_t previous_gmp, std::uint16_t gmp, bool input_active, const ShiftRegisterSetup& setup,
            std::uint16_t fsc);
  // Scan skipping (quiet_interval.hpp): where step() can capture or shift.
  static void keep_quiet(QuietInterval& quiet, std::uint16_t gmp, const ShiftRegisterSetup& setup,
                         std::uint16_t fsc);
  // b[n], n = 1..256.
  [[nodiscard]] bool bit(int n) const { return bits_.test(static_cast<std::size_t>(n - 1)); }
  [[nodiscard]] bool capture() const { return capture_; }
  // DA20 words 4..19: word 4 bit 0 = b[1] ... word 19 bit 15 = b[256].
  [[nodiscard]] std::array<std::uint16_t, 16> words() const;
  void clear() { *this = ShiftRegister{}; }

private:
  std::bitset<kShiftRegisterBits> bits_;
  bool capture_ = false;
  friend bool operator==(const ShiftRegister&, const ShiftRegister&) = default;
};

} // namespace hilrig::models::ans1
