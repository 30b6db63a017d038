#pragma once
// CAN frames of the rig's front-end nodes (DESIGN "Backends"): the angle/speed stream a
// resolver-emulator node consumes, and the edge reports a capture node sends. Classic CAN,
// 8 bytes, Intel (little-endian) signals. The same layout is in rt-config/can/hilrig-frontend.dbc;
// a test parses that file and checks it against the tables here.
//
// ResolverAngle (0x120, rig -> RESOLVER_EMU), one per channel per update:
//   bit 0  len 24  angle     unsigned, 1/2^24 turn (0 .. 1 - 2^-24)
//   bit 24 len 24  speed     signed, 1/4096 turn/s (+-2048 turn/s), for interpolation
//   bit 48 len 4   sequence  +1 per frame per channel, mod 16 (the node counts lost frames)
//   bit 52 len 1   valid     1 = drive the stators, 0 = stators to zero (safe state)
//   bit 53 len 1   sin_open  fault injection: SIN winding open
//   bit 54 len 1   cos_open  fault injection: COS winding open
//   bit 56 len 4   channel   resolver channel 0..15
// The angle holds at the frame's end of frame (its receive timestamp); the node advances it
// at `speed` until the next frame.
//
// EdgeReport (0x130, CAPTURE -> rig), one per captured output edge:
//   bit 0  len 8   line        capture line 0..255
//   bit 8  len 1   level       level after the edge
//   bit 9  len 7   sequence    +1 per report, mod 128
//   bit 16 len 16  time_hi     bits 47..32 of the node's timestamp in ns
//   bit 32 len 32  time_ns     bits 31..0 of the node's timestamp in ns
// time = time_hi * 2^32 + time_ns: a 48-bit ns count (78 hours) from the node's epoch.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "core/can_frame.hpp"
#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig::signals {

// One signal as a DBC SG_ line states it (Intel byte order only).
struct DbcSignal {
  std::string_view name;
  unsigned start_bit;
  unsigned length;
  bool is_signed;
  double factor;
  double offset;
  double minimum;
  double maximum;
  std::string_view unit;
};

struct DbcMessage {
  std::string_view name;
  std::uint32_t id;
  unsigned dlc;
  std::string_view sender;
  std::string_view receiver;
  std::span<const DbcSignal> signals;
};

inline constexpr std::uint32_t kResolverAngleId = 0x120;
inline constexpr std::uint32_t kEdgeReportId = 0x130;

[[nodiscard]] const DbcMessage& resolver_angle_message();
[[nodiscard]] const DbcMessage& edge_report_message();

struct ResolverAngleFrame {
  std::uint8_t channel = 0;       // 0..15
  double angle_turns = 0.0;       // wrapped into [0, 1) and rounded to 1/2^24 turn on encode
  double speed_turns_per_s = 0.0; // rounded to 1/4096 turn/s, clamped to the field
  std::uint8_t sequence = 0;      // low 4 bits sent
  bool valid = true;
  bool sin_open = false;
  bool cos_open = false;
};

struct EdgeReportFrame {
  std::uint8_t line = 0;
  Level level = Level::Low;
  std::uint8_t sequence = 0; // low 7 bits sent
  Nanos timestamp{0};        // 0 .. 2^48 - 1 ns; throws on encode outside
};

[[nodiscard]] CanFrame encode(const ResolverAngleFrame& f);
[[nodiscard]] CanFrame encode(const EdgeReportFrame& f);
// Empty unless the ID, format (standard, data, 8 bytes) match.
[[nodiscard]] std::optional<ResolverAngleFrame> decode_resolver_angle(const CanFrame& frame);
[[nodiscard]] std::optional<EdgeReportFrame> decode_edge_report(const CanFrame& frame);

// Intel-order raw signal access (start bit = LSB position, as in DBC "@1").
[[nodiscard]] std::uint64_t get_raw(const CanFrame& frame, unsigned start_bit, unsigned length);
void put_raw(CanFrame& frame, unsigned start_bit, unsigned length, std::uint64_t raw);
// Physical value of a signal: raw (sign-extended if signed) * factor + offset.
[[nodiscard]] double get_physical(const CanFrame& frame, const DbcSignal& s);

} // namespace hilrig::signals
