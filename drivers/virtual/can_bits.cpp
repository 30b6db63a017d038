// Frame lengths on the wire: the bit layout and stuffing rules are summarised in can_bus.hpp.
#include <array>
#include <stdexcept>

#include "drivers/virtual/can_bus.hpp"

namespace hilrig::virt {
namespace {

// Longest unstuffed SOF..CRC of any frame: FD extended, 64 bytes: 41 + 512 + 21 bits.
constexpr std::size_t kMaxBits = 600;

// One bit into a CRC register (ISO 11898-1): the register shifts left, and the polynomial is
// added when its top bit differs from the input bit. Every CRC here steps with it.
constexpr std::uint32_t crc_step(const CanCrc& crc, std::uint32_t reg, unsigned bit) {
  const std::uint32_t top = 1U << (crc.width - 1U);
  const bool feedback = ((reg & top) != 0) != (bit != 0);
  reg = (reg << 1U) & ((top << 1U) - 1U);
  return feedback ? reg ^ crc.poly : reg;
}

// CRC-15 (kCanCrc15) a byte at a time: the register after 8 bit steps from (x << 7), input 0.
constexpr std::array<std::uint16_t, 256> kCrc15Bytes = [] {
  std::array<std::uint16_t, 256> table{};
  for (std::uint32_t x = 0; x < 256; ++x) {
    std::uint32_t reg = x << 7U;
    for (int i = 0; i < 8; ++i) reg = crc_step(kCanCrc15, reg, 0);
    table[x] = static_cast<std::uint16_t>(reg);
  }
  return table;
}();

// The bit stream packed 64 to a word, first bit sent in a word's top bit: a byte of it (any
// bit offset) is two shifts, so the stuff bits are counted a byte at a time (kStuffStep).
struct BitStream {
  std::array<std::uint64_t, kMaxBits / 64 + 2> words{};
  std::size_t n = 0;
  std::size_t brs = 0; // index of the BRS bit (FD only)

  // The low `count` (1..32) bits of v, most significant first.
  void push(std::uint32_t v, unsigned count) {
    const std::uint64_t bits = std::uint64_t{v} & ((std::uint64_t{1} << count) - 1U);
    const std::size_t word = n / 64;
    const auto off = static_cast<unsigned>(n % 64);
    if (off + count <= 64) {
      words[word] |= bits << (64U - off - count);
    } else {
      const unsigned rest = off + count - 64; // bits in the next word
      words[word] |= bits >> rest;
      words[word + 1] |= bits << (64U - rest);
    }
    n += count;
  }
  // can_crc(bits, n, kCanCrc15) of the bits so far: a byte of them in one table step, the last
  // n % 8 a bit at a time.
  [[nodiscard]] std::uint32_t crc15() const {
    std::uint32_t crc = kCanCrc15.init;
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) crc = ((crc << 8U) & 0x7FFFU) ^ kCrc15Bytes[((crc >> 7U) ^ byte(i)) & 0xFFU];
    for (; i < n; ++i) crc = crc_step(kCanCrc15, crc, bit(i));
    return crc;
  }
  [[nodiscard]] unsigned bit(std::size_t i) const {
    return static_cast<unsigned>(words[i / 64] >> (63U - i % 64)) & 1U;
  }
  // Bits i..i+7, bit i the byte's top bit.
  [[nodiscard]] unsigned byte(std::size_t i) const {
    const std::size_t word = i / 64;
    const auto off = static_cast<unsigned>(i % 64);
    std::uint64_t v = words[word] << off;
    if (off > 56) v |= words[word + 1] >> (64U - off);
    return static_cast<unsigned>(v >> 56U);
  }
};

// Dynamic stuffing as a state machine: the state is the last bit sent (stuff bits included)
// and how many equal bits end the stream (1..4; a fifth is followed by its complement, which
// starts a run of 1), or kStuffStart before the first bit. A state is 1 + 4 * bit + run - 1.
constexpr unsigned kStuffStart = 0;

struct StuffStepResult {
  unsigned state;
  bool stuffed; // this bit made a run of 5: a stuff bit follows it
};

constexpr StuffStepResult stuff_step(unsigned state, unsigned b) {
  unsigned run = 1;
  if (state != kStuffStart) {
    const unsigned prev = (state - 1U) / 4U;
    run = prev == b ? (state - 1U) % 4U + 2U : 1U;
  }
  if (run == 5) return {1U + 4U * (1U - b), true};
  return {1U + 4U * b + run - 1U, false};
}

// A byte (top bit first) from each state: the state after it (low 4 bits) and the stuff bits
// it needs (the rest).
constexpr std::array<std::array<std::uint8_t, 256>, 9> kStuffStep = [] {
  std::array<std::array<std::uint8_t, 256>, 9> table{};
  for (unsigned state = 0; state < 9; ++state) {
    for (unsigned v = 0; v < 256; ++v) {
      unsigned s = state;
      unsigned stuffed = 0;
      for (unsigned i = 8; i-- > 0;) {
        const StuffStepResult r = stuff_step(s, (v >> i) & 1U);
        s = r.state;
        stuffed += r.stuffed ? 1U : 0U;
      }
      table[state][v] = static_cast<std::uint8_t>(s | (stuffed << 4U));
    }
  }
  return table;
}();

bool fd_length_ok(std::uint8_t len) {
  return len <= 8 || len == 12 || len == 16 || len == 20 || len == 24 || len == 32 || len == 48 || len == 64;
}

} // namespace

void can_check_frame(const CanFrame& f) {
  if (f.id > (f.extended ? 0x1FFF'FFFFU : 0x7FFU))
    throw std::invalid_argument("CAN: identifier out of range");
  if (f.fd) {
    if (f.rtr) throw std::invalid_argument("CAN FD has no remote frames");
    if (!fd_length_ok(f.len)) throw std::invalid_argument("CAN FD: length is not a DLC length");
  } else {
    if (f.len > 8) throw std::invalid_argument("classic CAN: length above 8");
    if (f.brs || f.esi) throw std::invalid_argument("classic CAN: BRS/ESI are FD bits");
  }
}

namespace {

// SOF through the data field, unstuffed.
BitStream header_and_data(const CanFrame& f) {
  can_check_frame(f);
  BitStream s;
  s.push(0, 1); // SOF
  if (f.extended) {
    s.push(f.id >> 18, 11);
    s.push(1, 1); // SRR (recessive)
    s.push(1, 1); // IDE
    s.push(f.id & 0x3'FFFFU, 18);
    if (f.fd) {
      s.push(0, 1); // RRS
      s.push(1, 1); // FDF
      s.push(0, 1); // res
    } else {
      s.push(f.rtr ? 1U : 0U, 1);
      s.push(0, 2); // r1, r0
    }
  } else {
    s.push(f.id, 11);
    if (f.fd) {
      s.push(0, 1); // RRS
      s.push(0, 1); // IDE
      s.push(1, 1); // FDF
      s.push(0, 1); // res
    } else {
      s.push(f.rtr ? 1U : 0U, 1);
      s.push(0, 2); // IDE, r0
    }
  }
  if (f.fd) {
    s.brs = s.n;
    s.push(f.brs ? 1U : 0U, 1);
    s.push(f.esi ? 1U : 0U, 1);
  }
  s.push(can_len_to_dlc(f.len), 4);
  if (!f.rtr) { // four bytes a push, then the rest one by one
    std::size_t i = 0;
    for (; i + 4 <= f.len; i += 4) {
      s.push(std::uint32_t{f.data[i]} << 24U | std::uint32_t{f.data[i + 1]} << 16U |
                 std::uint32_t{f.data[i + 2]} << 8U | f.data[i + 3],
             32);
    }
    for (; i < f.len; ++i) s.push(f.data[i], 8);
  }
  return s;
}

// Trailing bits, never stuffed: CRC delimiter, ACK slot, ACK delimiter, EOF (7), intermission (3).
constexpr std::uint32_t kTail = 1 + 1 + 1 + 7 + 3;

std::uint32_t fd_crc_width(const CanFrame& f) { return f.len <= 16 ? 17U : 21U; }
// One fixed stuff bit before the stuff count, then one after every 4 bits of count + CRC.
std::uint32_t fd_fixed_stuff(const CanFrame& f) { return 1U + (4U + fd_crc_width(f) - 1U) / 4U; }

struct StuffCount {
  std::uint32_t nominal = 0;
  std::uint32_t data = 0;
};

// Counts dynamic stuff bits: after 5 equal bits (stuff bits included) a complement is sent,
// which starts the next run. `last_stuffed` says whether a stuff bit due after the final bit
// is sent (classic CRC end: yes; FD data end: no, the fixed stuff bit takes its place). With
// split_at_brs, a stuff bit after a bit at or past the BRS bit is a data-phase bit.
StuffCount count_stuff(const BitStream& s, bool last_stuffed, bool split_at_brs) {
  StuffCount c;
  unsigned state = kStuffStart;
  // Bits [from, to) into `count`, a byte at a time, then a bit at a time.
  const auto run = [&](std::size_t from, std::size_t to, std::uint32_t& count) {
    std::size_t i = from;
    for (; i + 8 <= to; i += 8) {
      const std::uint8_t next = kStuffStep[state][s.byte(i)];
      state = next & 0xFU;
      count += next >> 4U;
    }
    for (; i < to; ++i) {
      const StuffStepResult r = stuff_step(state, s.bit(i));
      state = r.state;
      count += r.stuffed ? 1U : 0U;
    }
  };
  // The last bit's stuff bit, when it is not sent, is not counted: it does not change the count
  // of any bit before it.
  const std::size_t end = last_stuffed ? s.n : s.n - 1;
  if (split_at_brs) {
    const std::size_t brs = s.brs < end ? s.brs : end;
    run(0, brs, c.nominal);
    run(brs, end, c.data);
  } else {
    run(0, end, c.nominal);
  }
  return c;
}

CanFrameBits assemble(const CanFrame& f, const BitStream& s, StuffCount dyn) {
  CanFrameBits bits;
  const auto n = static_cast<std::uint32_t>(s.n);
  if (!f.fd) {
    bits.nominal = n + dyn.nominal + kTail;
    bits.stuff = dyn.nominal;
    return bits;
  }
  const std::uint32_t crc_part = 4U + fd_crc_width(f) + fd_fixed_stuff(f);
  bits.stuff = dyn.nominal + dyn.data + fd_fixed_stuff(f);
  if (f.brs) {
    const auto up_to_brs = static_cast<std::uint32_t>(s.brs) + 1U;
    bits.nominal = up_to_brs + dyn.nominal + kTail;
    bits.data = (n - up_to_brs) + dyn.data + crc_part;
  } else {
    bits.nominal = n + dyn.nominal + dyn.data + crc_part + kTail;
  }
  return bits;
}

} // namespace

std::uint32_t can_crc(const std::uint8_t* bits, std::size_t count, const CanCrc& crc) {
  std::uint32_t reg = crc.init & ((1U << crc.width) - 1U);
  for (std::size_t i = 0; i < count; ++i) reg = crc_step(crc, reg, bits[i]);
  return reg;
}

std::uint8_t can_dlc_to_len(std::uint8_t dlc, bool fd) {
  static constexpr std::array<std::uint8_t, 16> kFd{0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  if (dlc > 15) throw std::invalid_argument("CAN: DLC above 15");
  return fd ? kFd[dlc] : static_cast<std::uint8_t>(dlc > 8 ? 8 : dlc);
}

std::uint8_t can_len_to_dlc(std::uint8_t len) {
  if (len <= 8) return len;
  if (len <= 12) return 9;
  if (len <= 16) return 10;
  if (len <= 20) return 11;
  if (len <= 24) return 12;
  if (len <= 32) return 13;
  if (len <= 48) return 14;
  return 15;
}

CanFrameBits can_frame_bits(const CanFrame& frame) {
  BitStream s = header_and_data(frame);
  if (!frame.fd) {
    s.push(s.crc15(), 15); // can_crc of SOF..data (kCanCrc15)
    return assemble(frame, s, count_stuff(s, true, false));
  }
  return assemble(frame, s, count_stuff(s, false, frame.brs));
}

CanFrameBits can_frame_bits_worst(const CanFrame& frame) {
  BitStream s = header_and_data(frame);
  StuffCount dyn;
  if (!frame.fd) {
    s.push(0, 15); // the CRC field's length (its value does not matter here)
    // The stuffed region is SOF..CRC; the first stuff bit after 5 bits, then one every 4.
    dyn.nominal = (static_cast<std::uint32_t>(s.n) - 1U) / 4U;
    return assemble(frame, s, dyn);
  }
  // FD: SOF..data, without a stuff bit after the last data bit; the k-th stuff bit follows
  // unstuffed bit index 4k.
  const std::uint32_t count = (static_cast<std::uint32_t>(s.n) - 2U) / 4U;
  for (std::uint32_t k = 1; k <= count; ++k) {
    (frame.brs && std::size_t{4U} * k >= s.brs ? dyn.data : dyn.nominal) += 1;
  }
  return assemble(frame, s, dyn);
}

Nanos can_frame_duration(const CanFrameBits& bits, const CanBitTiming& timing) {
  const auto part = [](std::uint32_t count, std::uint32_t rate) {
    if (count == 0) return std::int64_t{0};
    if (rate == 0) throw std::invalid_argument("CAN: zero bitrate");
    const std::uint64_t num = std::uint64_t{count} * 1'000'000'000ULL;
    return static_cast<std::int64_t>((num + rate / 2) / rate);
  };
  return Nanos{part(bits.nominal, timing.nominal_bitrate) + part(bits.data, timing.data_bitrate)};
}

Nanos can_end_of_frame(const CanFrameBits& bits, const CanBitTiming& timing) {
  return can_frame_duration(bits, timing) - can_frame_duration(CanFrameBits{3, 0, 0}, timing);
}

std::vector<Nanos> can_end_of_frame_range(const CanFrame& frame, const CanBitTiming& timing) {
  if (frame.fd) throw std::invalid_argument("CAN: end-of-frame range of a classic frame only");
  const CanFrameBits worst = can_frame_bits_worst(frame);
  std::vector<Nanos> out;
  for (std::uint32_t stuff = 0; stuff <= worst.stuff; ++stuff)
    out.push_back(can_end_of_frame(CanFrameBits{worst.nominal - worst.stuff + stuff, 0, stuff}, timing));
  return out;
}

} // namespace hilrig::virt
