#include "core/candump.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "core/trace.hpp"

namespace hilrig {
namespace {

constexpr char kHex[] = "0123456789ABCDEF";

void put_hex(std::string& out, std::uint32_t v, int digits) {
  for (int i = digits - 1; i >= 0; --i) {
    out.push_back(kHex[(v >> (4 * i)) & 0xFU]);
  }
}

void put_decimal(std::string& out, std::int64_t v, int width) {
  std::string digits = std::to_string(v);
  if (digits.size() < static_cast<std::size_t>(width)) {
    out.append(static_cast<std::size_t>(width) - digits.size(), '0');
  }
  out += digits;
}

} // namespace

std::string candump_frame_text(const CanFrame& frame, bool fdf_flag) {
  std::string out;
  out.reserve(12U + 2U * frame.len);
  if (frame.extended) {
    put_hex(out, frame.id & 0x1FFF'FFFFU, 8);
  } else {
    put_hex(out, frame.id & 0x7FFU, 3);
  }
  out.push_back('#');
  if (!frame.fd && frame.rtr) {
    // A remote frame carries no data; a non-zero DLC is printed as one digit.
    out.push_back('R');
    if (frame.len > 0 && frame.len <= 8) out.push_back(kHex[frame.len]);
    return out;
  }
  if (frame.fd) {
    const std::uint32_t flags = (frame.brs ? 0x1U : 0U) | (frame.esi ? 0x2U : 0U) | (fdf_flag ? 0x4U : 0U);
    out.push_back('#');
    out.push_back(kHex[flags]);
  }
  const std::size_t len = std::min<std::size_t>(frame.len, frame.data.size());
  for (std::size_t i = 0; i < len; ++i) {
    put_hex(out, frame.data[i], 2);
  }
  return out;
}

std::string candump_line(Nanos t, std::string_view bus, const CanFrame& frame, std::size_t name_width,
                         bool fdf_flag) {
  if (t < Nanos::zero()) {
    throw std::invalid_argument("candump: negative timestamp");
  }
  const std::int64_t ns = t.count();
  std::string out;
  out.reserve(40U + 2U * frame.len);
  out.push_back('(');
  put_decimal(out, ns / 1'000'000'000, 10);
  out.push_back('.');
  put_decimal(out, (ns % 1'000'000'000) / 1'000, 6);
  out += ") ";
  if (bus.size() < name_width) out.append(name_width - bus.size(), ' ');
  out += bus;
  out.push_back(' ');
  out += candump_frame_text(frame, fdf_flag);
  return out;
}

void write_candump(const TraceRecorder& trace, std::ostream& out, const CandumpOptions& options) {
  std::size_t width = 0;
  for (const TraceCanFrame& f : trace.can_frames()) width = std::max(width, f.bus.size());
  for (const TraceCanFrame& f : trace.can_frames()) {
    out << candump_line(f.time + options.epoch, f.bus, f.frame, width, options.fdf_flag) << '\n';
  }
}

} // namespace hilrig
