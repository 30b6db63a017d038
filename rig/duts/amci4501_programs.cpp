// The 4501's programming cycle in its manual's words (docs/spec/amci4501.md §5.3; manual
// seeds/001, Lnnn): control word 0 selects the mode (bits 2-6 = modes 2-6, none = mode 1,
// L151-L161), word 1 the timeout (modes 1-4), words 2-5 the mode 2 enable window as
// value div 1000 / value mod 1000 (L131-L147, L170).

#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "rig/duts/device_programs.hpp"

namespace hilrig::duts {
namespace {

using Words = std::vector<std::uint16_t>;

struct Mode {
  std::int64_t mode = 1;
  std::int64_t timeout_ms = 0;
  std::int64_t on = 0;
  std::int64_t off = 0;
  bool acknowledge = false;
  bool clear_error = false;
};
Words mode(const Mode& m) {
  const auto w0 = static_cast<std::uint16_t>(bit(static_cast<unsigned>(m.mode), m.mode != 1) |
                                             bit(1, m.clear_error) | bit(0, m.acknowledge));
  if (m.mode != 2) {
    if (m.on != 0 || m.off != 0) throw ProgramFieldError("on", "an enable window only with mode = 2 (L170)");
    return {w0, word(m.timeout_ms)};
  }
  // "The enable window on setpoint must be less than the enable window off setpoint" (L171); a
  // deliberately invalid window, to provoke the Parameter Error, is written raw. The setpoints
  // end at 65,535 (L172), so no off setpoint lies above an on setpoint of 65,535.
  if (m.on >= 65535)
    throw ProgramFieldError("on", "no off setpoint exists above 65535 (L172: 0 .. 65535; L171: on below "
                                  "off), so the on setpoint must be at most 65534");
  if (m.on >= m.off)
    throw ProgramFieldError(
        "off", fmt::format("must be above the on setpoint {} (L171): {} .. 65535", m.on, m.on + 1));
  return {
      w0, word(m.timeout_ms), word(m.on / 1000), word(m.on % 1000), word(m.off / 1000), word(m.off % 1000)};
}

} // namespace

std::vector<ProgramBlockInfo> amci4501_programs() {
  return {
      program_block<Mode>(
          "mode", "a programming cycle: the mode, its timeout and mode 2's enable window (L151-L176)",
          {
              {"mode", &Mode::mode, "the measurement mode (L7-L57)", 1, 6},
              {"timeout_ms",
               &Mode::timeout_ms,
               "the timeout, ms (word 1; 0 = 10 s, L169)",
               0,
               32767,
               {},
               true},
              {"on", &Mode::on, "mode 2: the on setpoint, counts (L170-L174)", 0, 65535, {}, true},
              {"off", &Mode::off, "mode 2: the off setpoint, counts", 0, 65535, {}, true},
              {"acknowledge", &Mode::acknowledge, "control bit 0 Received Measurement (L153)"},
              {"clear_error", &Mode::clear_error, "control bit 1 Clear Measurement Error (L154)"},
          },
          &mode),
  };
}

} // namespace hilrig::duts
