#include "signals/resolver_frames.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace hilrig::signals {

namespace {

constexpr double kAngleLsb = 1.0 / 16'777'216.0; // 2^-24 turn
constexpr double kSpeedLsb = 1.0 / 4096.0;       // turn/s

constexpr std::array<DbcSignal, 7> kResolverAngleSignals{{
    {"angle", 0, 24, false, kAngleLsb, 0.0, 0.0, 1.0 - kAngleLsb, "turn"},
    {"speed", 24, 24, true, kSpeedLsb, 0.0, -2048.0, 2048.0 - kSpeedLsb, "turn/s"},
    {"sequence", 48, 4, false, 1.0, 0.0, 0.0, 15.0, ""},
    {"valid", 52, 1, false, 1.0, 0.0, 0.0, 1.0, ""},
    {"sin_open", 53, 1, false, 1.0, 0.0, 0.0, 1.0, ""},
    {"cos_open", 54, 1, false, 1.0, 0.0, 0.0, 1.0, ""},
    {"channel", 56, 4, false, 1.0, 0.0, 0.0, 15.0, ""},
}};

constexpr std::array<DbcSignal, 5> kEdgeReportSignals{{
    {"line", 0, 8, false, 1.0, 0.0, 0.0, 255.0, ""},
    {"level", 8, 1, false, 1.0, 0.0, 0.0, 1.0, ""},
    {"sequence", 9, 7, false, 1.0, 0.0, 0.0, 127.0, ""},
    {"time_hi", 16, 16, false, 4294967296.0, 0.0, 0.0, 281470681743360.0, "ns"},
    {"time_ns", 32, 32, false, 1.0, 0.0, 0.0, 4294967295.0, "ns"},
}};

constexpr DbcMessage kResolverAngle{"ResolverAngle", kResolverAngleId, 8,
                                    "HILRIG",        "RESOLVER_EMU",   kResolverAngleSignals};
constexpr DbcMessage kEdgeReport{"EdgeReport", kEdgeReportId, 8, "CAPTURE", "HILRIG", kEdgeReportSignals};

CanFrame blank(std::uint32_t id) {
  CanFrame f;
  f.id = id;
  f.len = 8;
  return f;
}

bool matches(const CanFrame& f, std::uint32_t id) {
  return f.id == id && !f.extended && !f.rtr && !f.fd && f.len == 8;
}

// The 8 data bytes from a 64-bit payload whose bit k is the frame's bit k (the little-endian
// layout put_raw gives each signal: byte k / 8, bit k % 8 of it).
void store_payload(CanFrame& frame, std::uint64_t payload) {
  for (std::size_t i = 0; i < 8; ++i) frame.data[i] = static_cast<std::uint8_t>(payload >> (8U * i));
}

std::int64_t sign_extend(std::uint64_t raw, unsigned length) {
  const std::uint64_t sign = 1ull << (length - 1);
  return static_cast<std::int64_t>(raw ^ sign) - static_cast<std::int64_t>(sign);
}

} // namespace

const DbcMessage& resolver_angle_message() { return kResolverAngle; }
const DbcMessage& edge_report_message() { return kEdgeReport; }

// Both a byte's part of the signal at a time: (start_bit + i) % 8 is where bit i of the
// signal sits in its byte, and a byte holds up to 8 - that of the signal's bits.
std::uint64_t get_raw(const CanFrame& frame, unsigned start_bit, unsigned length) {
  std::uint64_t v = 0;
  for (unsigned i = 0; i < length;) {
    const unsigned bit = start_bit + i;
    const unsigned shift = bit % 8;
    const unsigned take = std::min(8U - shift, length - i);
    const unsigned part = (static_cast<unsigned>(frame.data[bit / 8]) >> shift) & ((1U << take) - 1U);
    v |= std::uint64_t{part} << i;
    i += take;
  }
  return v;
}

void put_raw(CanFrame& frame, unsigned start_bit, unsigned length, std::uint64_t raw) {
  for (unsigned i = 0; i < length;) {
    const unsigned bit = start_bit + i;
    const unsigned shift = bit % 8;
    const unsigned take = std::min(8U - shift, length - i);
    const unsigned mask = ((1U << take) - 1U) << shift;
    const auto part = static_cast<unsigned>((raw >> i) << shift) & mask;
    std::uint8_t& byte = frame.data[bit / 8];
    byte = static_cast<std::uint8_t>((byte & ~mask) | part);
    i += take;
  }
}

double get_physical(const CanFrame& frame, const DbcSignal& s) {
  const std::uint64_t raw = get_raw(frame, s.start_bit, s.length);
  const double v = s.is_signed ? static_cast<double>(sign_extend(raw, s.length)) : static_cast<double>(raw);
  return v * s.factor + s.offset;
}

CanFrame encode(const ResolverAngleFrame& f) {
  CanFrame out = blank(kResolverAngleId);
  const double wrapped = f.angle_turns - std::floor(f.angle_turns);
  const auto angle = static_cast<std::uint64_t>(std::llround(wrapped * 16'777'216.0)) & 0xFF'FFFFu;
  const double speed_counts = std::round(f.speed_turns_per_s * 4096.0);
  const double clamped = std::fmax(-8'388'608.0, std::fmin(8'388'607.0, speed_counts));
  const auto speed = static_cast<std::uint64_t>(static_cast<std::int64_t>(clamped)) & 0xFF'FFFFu;
  // The signals of kResolverAngleSignals at their start bits, in one payload.
  store_payload(out, angle | speed << 24U | std::uint64_t{f.sequence & 0xFu} << 48U |
                         std::uint64_t{f.valid ? 1u : 0u} << 52U |
                         std::uint64_t{f.sin_open ? 1u : 0u} << 53U |
                         std::uint64_t{f.cos_open ? 1u : 0u} << 54U | std::uint64_t{f.channel & 0xFu} << 56U);
  return out;
}

std::optional<ResolverAngleFrame> decode_resolver_angle(const CanFrame& frame) {
  if (!matches(frame, kResolverAngleId)) return std::nullopt;
  ResolverAngleFrame f;
  f.angle_turns = get_physical(frame, kResolverAngleSignals[0]);
  f.speed_turns_per_s = get_physical(frame, kResolverAngleSignals[1]);
  f.sequence = static_cast<std::uint8_t>(get_raw(frame, 48, 4));
  f.valid = get_raw(frame, 52, 1) != 0;
  f.sin_open = get_raw(frame, 53, 1) != 0;
  f.cos_open = get_raw(frame, 54, 1) != 0;
  f.channel = static_cast<std::uint8_t>(get_raw(frame, 56, 4));
  return f;
}

CanFrame encode(const EdgeReportFrame& f) {
  if (f.timestamp < Nanos{0} || f.timestamp.count() >= (std::int64_t{1} << 48))
    throw std::out_of_range("edge report timestamp must be 0 .. 2^48-1 ns");
  CanFrame out = blank(kEdgeReportId);
  const auto t = static_cast<std::uint64_t>(f.timestamp.count());
  // The signals of kEdgeReportSignals at their start bits, in one payload (t < 2^48).
  store_payload(out, std::uint64_t{f.line} | std::uint64_t{is_high(f.level) ? 1u : 0u} << 8U |
                         std::uint64_t{f.sequence & 0x7Fu} << 9U | (t >> 32U) << 16U |
                         (t & 0xFFFF'FFFFu) << 32U);
  return out;
}

std::optional<EdgeReportFrame> decode_edge_report(const CanFrame& frame) {
  if (!matches(frame, kEdgeReportId)) return std::nullopt;
  EdgeReportFrame f;
  f.line = static_cast<std::uint8_t>(get_raw(frame, 0, 8));
  f.level = level_of(get_raw(frame, 8, 1) != 0);
  f.sequence = static_cast<std::uint8_t>(get_raw(frame, 9, 7));
  const std::uint64_t t = (get_raw(frame, 16, 16) << 32) | get_raw(frame, 32, 32);
  f.timestamp = Nanos{static_cast<std::int64_t>(t)};
  return f;
}

} // namespace hilrig::signals
