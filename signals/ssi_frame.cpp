#include "signals/ssi_frame.hpp"

#include <bit>
#include <stdexcept>
#include <string>

#include "signals/gray_code.hpp"

namespace hilrig::signals {

namespace {

// Places `width` bits of `v` so that their MSB is stream bit `first` (1-based).
std::uint64_t place(std::uint64_t v, unsigned frame_bits, unsigned first, unsigned width) {
  const unsigned shift = frame_bits - (first - 1) - width;
  return (v & low_mask(width)) << shift;
}

std::uint32_t extract(std::uint32_t word, unsigned frame_bits, unsigned first, unsigned width) {
  const unsigned shift = frame_bits - (first - 1) - width;
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(word) >> shift) & low_mask(width));
}

bool parity_bit(const SsiFrameFormat& f, std::uint32_t data_field, std::uint32_t status) {
  const int ones = std::popcount(data_field) + std::popcount(status & low_mask(f.status_bits));
  const bool odd_ones = (ones % 2) != 0;
  // Even parity: the bit makes the total count of ones even; odd parity: odd.
  return f.parity == SsiParity::Even ? odd_ones : !odd_ones;
}

} // namespace

unsigned SsiFrameFormat::parity_position() const {
  const unsigned data_end = data_msb + data_bits - 1;
  const unsigned status_end = status_bits == 0 ? 0 : status_first() + status_bits - 1;
  return (data_end > status_end ? data_end : status_end) + 1;
}

unsigned SsiFrameFormat::used_bits() const {
  return parity_position() - (parity == SsiParity::None ? 1u : 0u);
}

void SsiFrameFormat::validate() const {
  if (frame_bits < 1 || frame_bits > 32)
    throw std::invalid_argument("SSI frame_bits must be 1..32, got " + std::to_string(frame_bits));
  if (data_bits < 1 || data_bits > 32)
    throw std::invalid_argument("SSI data_bits must be 1..32, got " + std::to_string(data_bits));
  if (data_msb < 1) throw std::invalid_argument("SSI data_msb is 1-based");
  if (status_bits > 31) throw std::invalid_argument("SSI status_bits must be <= 31");
  if (status_bits > 0 && status_msb != 0) {
    const unsigned s_end = status_msb + status_bits - 1;
    const unsigned d_end = data_msb + data_bits - 1;
    if (!(s_end < data_msb || status_msb > d_end))
      throw std::invalid_argument("SSI status bits overlap the data field");
  }
  if (used_bits() > frame_bits)
    throw std::invalid_argument("SSI fields need " + std::to_string(used_bits()) + " bits, frame has " +
                                std::to_string(frame_bits));
}

SsiFrameFormat ssi7361_frame(unsigned msb, unsigned bits, SsiCode code) {
  SsiFrameFormat f;
  f.frame_bits = 25;
  f.data_msb = msb;
  f.data_bits = bits;
  f.code = code;
  f.validate();
  return f;
}

std::uint32_t compose_frame(const SsiFrameFormat& f, std::uint32_t value, std::uint32_t status) {
  std::uint32_t field = value & low_mask(f.data_bits);
  if (f.code == SsiCode::Gray) field = binary_to_gray(field);
  std::uint64_t word = place(field, f.frame_bits, f.data_msb, f.data_bits);
  word |= place(status, f.frame_bits, f.status_first(), f.status_bits);
  if (f.parity != SsiParity::None) {
    const std::uint64_t p = parity_bit(f, field, status) ? 1u : 0u;
    word |= place(p, f.frame_bits, f.parity_position(), 1);
  }
  return static_cast<std::uint32_t>(word);
}

SsiFrameFields decompose_frame(const SsiFrameFormat& f, std::uint32_t word) {
  SsiFrameFields out;
  const std::uint32_t field = extract(word, f.frame_bits, f.data_msb, f.data_bits);
  out.value = f.code == SsiCode::Gray ? gray_to_binary(field) : field;
  out.status = extract(word, f.frame_bits, f.status_first(), f.status_bits);
  if (f.parity != SsiParity::None) {
    const bool sent = extract(word, f.frame_bits, f.parity_position(), 1) != 0;
    out.parity_ok = sent == parity_bit(f, field, out.status);
  }
  return out;
}

} // namespace hilrig::signals
