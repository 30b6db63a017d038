#pragma once
// can-utils' candump log format (candump -l, read by canplayer and log2asc), one frame a line:
//   (0000000012.345678) can0 123#DEADBEEF      classic, standard ID (3 hex digits)
//   (0000000012.345678) can0 12345678#R2       classic remote frame, extended ID (8 digits), DLC 2
//   (0000000012.345678) can0 123##1DEADBEEF    CAN FD: '##', one flags nibble, then the data
// The flags nibble is canfd_frame.flags as lib.c's sprint_canframe() prints it: CANFD_BRS (1)
// | CANFD_ESI (2), plus CANFD_FDF (4) when fdf_flag is set -- Linux 6.0+ sets FDF on every
// CAN FD frame a CAN driver receives (alloc_canfd_skb), so candump -l on such a kernel writes
// "123##5..." for a BRS frame. canplayer and log2asc read both forms.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "core/can_frame.hpp"
#include "core/time.hpp"

namespace hilrig {

// "123#DEADBEEF": the frame part of a line (sprint_canframe with no separator).
[[nodiscard]] std::string candump_frame_text(const CanFrame& frame, bool fdf_flag = false);

// A whole line without its '\n'. The timestamp is truncated to microseconds, as the kernel's
// timeval is; seconds are zero-padded to 10 digits ("%010lu.%06lu"). The bus name is
// right-aligned to name_width, as candump pads interface names to the longest one it logs.
// Throws std::invalid_argument for a negative time.
[[nodiscard]] std::string candump_line(Nanos t, std::string_view bus, const CanFrame& frame,
                                       std::size_t name_width = 0, bool fdf_flag = false);

// One line of a candump log as read back: what candump_line() writes.
struct CandumpRecord {
  Nanos time;
  std::string bus;
  CanFrame frame;
  bool fdf_flag = false; // the FD flags nibble had CANFD_FDF (4)
  friend bool operator==(const CandumpRecord&, const CandumpRecord&) = default;
};

// Reads one line (without its '\n') in exactly the forms above: "(SECONDS.MICROS) BUS FRAME",
// the seconds 1..10 digits (at most 9223372035, what nanoseconds in 64 bits hold) and the
// microseconds 6, the bus name 1..15 characters (IFNAMSIZ)
// after any padding, a 3-digit standard or 8-digit extended ID, at most 8 data bytes on a
// classic frame and a CAN FD length (0..8, 12, 16, 20, 24, 32, 48, 64) on an FD frame.
// nullopt for anything else: a log is evidence, and a line that is not one is not guessed at.
[[nodiscard]] std::optional<CandumpRecord> read_candump_line(std::string_view line);

} // namespace hilrig
