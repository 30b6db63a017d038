#pragma once
// Output enabling (spec §4.8): speed window, input ANDing (simple, pulse, window). Each
// unconfigured condition reads 1.
#include <cstdint>

#include "models/ans1/output_setup.hpp"

namespace hilrig::models::ans1 {

// Speed enabling on the reported (integer) speed. Low == High == 0: not used. Low < High:
// Low <= S <= High. Low > High: S < High or S > Low. Low == High != 0 (A40): [MODEL] S == Low.
[[nodiscard]] bool speed_enabled(std::int16_t low, std::int16_t high, std::int16_t speed);

// The inputs (bit n-1 = input n) an output ANDs in the given mode.
[[nodiscard]] std::uint16_t anding_mask(const OutputSetup& setup, AndingMode mode);

// A window on GMP [Low, High], both ends inclusive ([MODEL]); Low > High wraps through zero.
[[nodiscard]] bool in_window(std::uint16_t p, std::uint16_t low, std::uint16_t high);

// Pulse ANDing (L965): each pulse input latches once it is active while the position is
// inside a pair; entering a pair clears the latches. With several pulse inputs each has its
// own latch and all must be set ([MODEL]).
class PulseLatch {
public:
  // pair: index of the pair the position is in, or -1.
  bool step(int pair, std::uint16_t active_inputs, std::uint16_t pulse_inputs);
  void reset() { *this = PulseLatch{}; }

private:
  int pair_ = -1;
  std::uint16_t latched_ = 0;
  friend bool operator==(const PulseLatch&, const PulseLatch&) = default;
};

// Window ANDing (L972): entering the window clears W; the window input active inside the
// window sets it; W holds until the window is reached again. W = 0 at power-up ([MODEL]).
class WindowLatch {
public:
  bool step(bool inside, bool input_active);
  void reset() { *this = WindowLatch{}; }

private:
  bool inside_ = false;
  bool w_ = false;
  friend bool operator==(const WindowLatch&, const WindowLatch&) = default;
};

} // namespace hilrig::models::ans1
