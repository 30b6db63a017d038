#pragma once
// The bit layout of one SSI frame, as the 7361 digest describes its 25-bit frame
// (ssi7361.md §2.1, §2.3): stream bit 1 is clocked out first and is the word's MSB; a data
// field of N bits starts at stream bit M (MSB first), binary or Gray; optional status bits
// (or, like the Balluff error bit at stream bit 3, L2309-2311, sit before it) and a parity
// bit follows the last field. Unused stream bits are sent as 0.

#include <cstdint>

namespace hilrig::signals {

enum class SsiCode : std::uint8_t { Binary, Gray };
enum class SsiParity : std::uint8_t { None, Even, Odd };

struct SsiFrameFormat {
  unsigned frame_bits = 25; // clocks per frame, 1..32 (the 7361 always clocks 25, L967)
  unsigned data_msb = 1;    // stream bit (1-based) of the data field's MSB: the 7361's "M"
  unsigned data_bits = 24;  // data field width, 1..32: the 7361's "N"
  SsiCode code = SsiCode::Binary;
  unsigned status_bits = 0;           // status/error bits, first-sent bit is the MSB
  unsigned status_msb = 0;            // stream bit of the first status bit; 0 = right after the data
  SsiParity parity = SsiParity::None; // one bit after the last field, over data and status

  [[nodiscard]] unsigned status_first() const { return status_msb == 0 ? data_msb + data_bits : status_msb; }
  [[nodiscard]] unsigned parity_position() const; // stream bit of the parity bit (if any)
  // The last stream bit any field occupies.
  [[nodiscard]] unsigned used_bits() const;
  // Throws std::invalid_argument unless every field fits inside frame_bits (1..32) and
  // the data and status fields do not overlap.
  void validate() const;
};

// A 7361-style frame: 25 clocks, data field of `bits` at stream bit `msb` (M + N <= 26).
[[nodiscard]] SsiFrameFormat ssi7361_frame(unsigned msb = 1, unsigned bits = 24,
                                           SsiCode code = SsiCode::Binary);

// The fields of one frame. `value` is the position in plain binary (Gray coding is the
// frame's business); `status` holds status_bits bits, first-sent bit as its MSB.
struct SsiFrameFields {
  std::uint32_t value = 0;
  std::uint32_t status = 0;
  bool parity_ok = true; // always true without a parity bit
  friend bool operator==(const SsiFrameFields&, const SsiFrameFields&) = default;
};

// The frame word: frame_bits wide, stream bit k at weight 2^(frame_bits - k). Values wider
// than the field are truncated to it. The format must be valid (not checked here).
[[nodiscard]] std::uint32_t compose_frame(const SsiFrameFormat& format, std::uint32_t value,
                                          std::uint32_t status = 0);
[[nodiscard]] SsiFrameFields decompose_frame(const SsiFrameFormat& format, std::uint32_t word);

// Stream bit k (1-based) of a frame word.
[[nodiscard]] constexpr bool stream_bit(std::uint32_t word, unsigned frame_bits, unsigned k) {
  return ((word >> (frame_bits - k)) & 1u) != 0;
}

} // namespace hilrig::signals
