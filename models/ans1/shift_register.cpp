#include "models/ans1/shift_register.hpp"

#include "models/ans1/position.hpp"

namespace hilrig::models::ans1 {

bool crossed_forward(std::uint16_t from, std::uint16_t to, std::uint16_t mark, std::uint16_t fsc) {
  const auto step = wrap(static_cast<std::int64_t>(to) - from, fsc);
  if (step == 0 || 2 * step >= fsc) {
    return false; // standing still, or moving backwards
  }
  const auto distance = wrap(static_cast<std::int64_t>(mark) - from, fsc);
  return distance > 0 && distance <= step;
}

void ShiftRegister::step(std::uint16_t previous_gmp, std::uint16_t gmp, bool input_active,
                         const ShiftRegisterSetup& setup, std::uint16_t fsc) {
  if (setup.input == 0) {
    return;
  }
  const SetpointPair window{setup.window_from, setup.window_to, 0, 0};
  const auto length = wrap(static_cast<std::int64_t>(window.to) - window.from, fsc);
  const auto d = wrap(static_cast<std::int64_t>(gmp) - window.from, fsc);
  if (d < length && input_active) {
    capture_ = true;
  }
  if (crossed_forward(previous_gmp, gmp, setup.shift_position, fsc)) {
    bits_ <<= 1;
    bits_.set(0, capture_);
    capture_ = false;
  }
}

void ShiftRegister::keep_quiet(QuietInterval& quiet, std::uint16_t gmp, const ShiftRegisterSetup& setup,
                               std::uint16_t fsc) {
  if (setup.input == 0) {
    return;
  }
  quiet.keep_arc(gmp, setup.window_from,
                 wrap(static_cast<std::int64_t>(setup.window_to) - setup.window_from, fsc), fsc);
  quiet.keep_before_mark(gmp, setup.shift_position);
}

std::array<std::uint16_t, 16> ShiftRegister::words() const {
  std::array<std::uint16_t, 16> w{};
  for (std::size_t i = 0; i < kShiftRegisterBits; ++i) {
    if (bits_.test(i)) {
      w[i / 16] = static_cast<std::uint16_t>(w[i / 16] | (1U << (i % 16)));
    }
  }
  return w;
}

} // namespace hilrig::models::ans1
