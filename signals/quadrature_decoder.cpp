#include "signals/quadrature_decoder.hpp"

#include <array>

namespace hilrig::signals {

namespace {
// Position of a state (A << 1 | B) in the forward cycle 00 -> 10 -> 11 -> 01.
constexpr std::array<std::uint8_t, 4> kPhase{0, 3, 1, 2};

std::uint8_t state_of(bool a, bool b) { return static_cast<std::uint8_t>((a ? 2U : 0U) | (b ? 1U : 0U)); }
} // namespace

QuadratureDecoder::QuadratureDecoder(CountMode mode, bool a, bool b) : mode_(mode), state_(state_of(a, b)) {}

int QuadratureDecoder::update(bool a, bool b) {
  const std::uint8_t next = state_of(a, b);
  if (next == state_) return 0;
  const std::uint8_t from = kPhase[state_];
  const std::uint8_t to = kPhase[next];
  state_ = next;
  const int step = (to - from) & 3; // 1 forward, 3 backward, 2 both channels changed
  if (step == 2) {
    ++illegal_;
    return 0;
  }
  const int delta = step == 1 ? 1 : -1;
  int change = 0;
  switch (mode_) {
  // X2 counts the edges of A: phases 0<->1 and 2<->3 (the pairs whose xor is 1).
  case CountMode::X4:
    change = delta;
    break;
  case CountMode::X2:
    change = (from ^ to) == 1 ? delta : 0;
    break;
  // X1 counts once per cycle, on A rising with B low (phase 0 -> 1) and its reverse.
  case CountMode::X1:
    change = (from == 0 && to == 1) || (from == 1 && to == 0) ? delta : 0;
    break;
  }
  count_ += change;
  return change;
}

void QuadratureDecoder::index(bool z) {
  if (z && !z_) {
    ++index_pulses_;
    index_count_ = count_;
    if (reset_on_index) count_ = 0;
  }
  z_ = z;
}

} // namespace hilrig::signals
