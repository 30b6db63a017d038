#include "models/ssi7361/data_path.hpp"

#include <limits>

#include "signals/gray_code.hpp"

namespace hilrig::models::ssi7361 {

std::uint32_t extract_field(std::uint32_t raw, unsigned msb, unsigned bits) {
  const unsigned shift = 26u - msb - bits; // >= 0 for any accepted setup (M + N <= 26)
  return (raw >> shift) & signals::low_mask(bits);
}

std::int64_t position_counts(std::uint32_t raw, const Setup& setup, const Params& params) {
  const unsigned n = setup.ssi.bits;
  const std::uint32_t mask = signals::low_mask(n);
  std::uint32_t field = extract_field(raw, setup.ssi.msb, n);
  // The GraySwapped variant reads the Data Type bit inverted.
  const bool gray = params.variant == Variant::GraySwapped ? !setup.ssi.gray : setup.ssi.gray;
  if (setup.ssi.negative_logic && params.invert_before_gray) field ^= mask;
  if (gray) field = signals::gray_to_binary(field) & mask;
  if (setup.ssi.negative_logic && !params.invert_before_gray) field ^= mask;
  if (!setup.count_negative) return field;
  if (params.count_direction_wrap && field == 0) return 0;
  return (std::int64_t{1} << n) - static_cast<std::int64_t>(field);
}

std::int64_t scale(std::int64_t x, std::uint16_t multiplier, std::uint16_t divisor) {
  return x * multiplier / divisor; // C++ division truncates toward zero
}

std::int64_t data_value(std::uint32_t raw, const Setup& setup, std::int64_t offset, const Params& params) {
  const std::int64_t x = position_counts(raw, setup, params);
  if (params.variant == Variant::OffsetBeforeScaling)
    return scale(x + offset, setup.multiplier, setup.divisor);
  return scale(x, setup.multiplier, setup.divisor) + offset;
}

std::int64_t preset_offset(std::uint32_t raw, const Setup& setup, const Params& params) {
  return static_cast<std::int64_t>(setup.preset) -
         scale(position_counts(raw, setup, params), setup.multiplier, setup.divisor);
}

std::int64_t rate_of_change(std::int64_t delta, std::uint16_t rut_ms, RateRounding rounding) {
  const std::int64_t num = delta * 1000;
  const std::int64_t den = rut_ms;
  if (rounding == RateRounding::Truncate) return num / den;
  // Half away from zero, exactly: (2|num| + den) / (2 den).
  return num >= 0 ? (2 * num + den) / (2 * den) : -((-2 * num + den) / (2 * den));
}

std::int32_t saturate_i32(std::int64_t v) {
  constexpr std::int64_t lo = std::numeric_limits<std::int32_t>::min();
  constexpr std::int64_t hi = std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(v < lo ? lo : (v > hi ? hi : v));
}

} // namespace hilrig::models::ssi7361
