#pragma once
// Serial byte links (UART, RS-485): framing and the narrow interface backends implement.

#include <cstdint>
#include <functional>
#include <span>

#include "core/time.hpp"

namespace hilrig {

enum class Parity : std::uint8_t { None, Even, Odd };

struct SerialFormat {
  std::uint32_t baud = 9600;
  std::uint8_t data_bits = 8;
  Parity parity = Parity::None;
  std::uint8_t stop_bits = 1;

  // Bits on the wire per character: start + data + parity + stop.
  [[nodiscard]] constexpr std::uint32_t bits_per_char() const {
    return 1U + data_bits + (parity == Parity::None ? 0U : 1U) + stop_bits;
  }
  // Duration of one character, rounded to the nearest nanosecond.
  [[nodiscard]] constexpr Nanos char_time() const {
    const std::int64_t num = static_cast<std::int64_t>(bits_per_char()) * 1'000'000'000;
    return Nanos{(num + baud / 2) / baud};
  }
};

using ByteHandler = std::function<void(std::uint8_t byte, Nanos timestamp)>;

// One end of a full-duplex byte link.
class ByteLink {
public:
  virtual ~ByteLink() = default;
  virtual void write(std::span<const std::uint8_t> bytes) = 0;
  // Called for each byte received, stamped when its stop bit ends.
  virtual void on_byte(ByteHandler handler) = 0;
};

} // namespace hilrig
