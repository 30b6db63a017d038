// The Series 2700's BTW instructions in its manual's words (docs/spec/pls2700.md §5.3; manual
// seeds/002, Lnnn): each block is one BTW of one instruction, [n, command, data...], its data in
// BCD (L1330, L1366-L1393). Several instructions in one BTW stay raw `write` words.

#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "rig/duts/device_programs.hpp"

namespace hilrig::duts {
namespace {

using Words = std::vector<std::uint16_t>;
using Opt = std::optional<std::int64_t>;

std::uint16_t bcd(std::int64_t v) {
  std::uint16_t out = 0;
  for (unsigned shift = 0; v > 0 && shift < 16; shift += 4, v /= 10)
    out = static_cast<std::uint16_t>(out | ((v % 10) << shift));
  return out;
}

Words btw(Words instruction) {
  instruction.insert(instruction.begin(), word(static_cast<std::int64_t>(instruction.size())));
  return instruction;
}

// 8400h Clear Errors: programming errors and transducer faults (L1359).
struct ClearErrors {};
Words clear_errors(const ClearErrors&) { return btw({0x8400}); }

// 88XYh channel 1 transducer setup (L1366-L1370): Y bit 0 Scale Factor, bit 1 Circular Offset,
// bit 2 the Tach Response word; data in that order.
struct Setup {
  Opt scale_factor;
  Opt circular_offset;
  Opt tach_response;
};
Words setup(const Setup& s) {
  Words w{0x8800};
  const Opt data[] = {s.scale_factor, s.circular_offset, s.tach_response};
  for (unsigned k = 0; k < 3; ++k) {
    if (!data[k]) continue;
    w[0] = static_cast<std::uint16_t>(w[0] | bit(k));
    w.push_back(bcd(*data[k]));
  }
  if (w.size() == 1)
    throw ProgramFieldError("scale_factor", "at least one of scale_factor, circular_offset, tach_response");
  return btw(std::move(w));
}

// C0XYh one output's limit with Y = 1 pair (L1392-L1393): the advance word (ON advance BCD in
// the high byte, OFF in the low), then ON and OFF.
struct Limits {
  std::int64_t output = 1;
  std::int64_t on = 0;
  std::int64_t off = 0;
  std::int64_t on_advance_ms = 0;
  std::int64_t off_advance_ms = 0;
};
Words limits(const Limits& l) {
  return btw({static_cast<std::uint16_t>(0xC001U | (l.output << 4)),
              static_cast<std::uint16_t>((bcd(l.on_advance_ms) << 8) | bcd(l.off_advance_ms)), bcd(l.on),
              bcd(l.off)});
}

} // namespace

std::vector<ProgramBlockInfo> pls2700_programs() {
  return {
      program_block<ClearErrors>("clear_errors", "8400h Clear Errors (L1359)", {}, &clear_errors),
      program_block<Setup>(
          "setup", "88XYh channel 1 setup; each setting given is sent (L1366-L1370, L1369 ranges)",
          {
              {"scale_factor", &Setup::scale_factor, "Scale Factor (2 .. 1024 or 4096 by model)", 2, 4096},
              {"circular_offset", &Setup::circular_offset, "Circular Offset (0 .. SF-1)", 0, 4095},
              {"tach_response", &Setup::tach_response, "Tach Response code (L1369)", 0, 4},
          },
          &setup),
      program_block<Limits>(
          "limits", "C0X1h one ON/OFF pair of an output with its advances, ms (L1392-L1393, L413-L415)",
          {
              {"output", &Limits::output, "the output", 1, 8},
              {"on", &Limits::on, "the ON setpoint (0 .. SF-1)", 0, 4095},
              {"off", &Limits::off, "the OFF setpoint (0 .. SF-1)", 0, 4095},
              {"on_advance_ms", &Limits::on_advance_ms, "ON advance, ms", 0, 99, {}, true},
              {"off_advance_ms",
               &Limits::off_advance_ms,
               "OFF advance, ms (<= ON but on -04 models)",
               0,
               99,
               {},
               true},
          },
          &limits),
  };
}

} // namespace hilrig::duts
