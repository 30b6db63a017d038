#include "core/trace.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "core/candump.hpp"

namespace hilrig {
namespace {

const SignalInfo& checked(const std::vector<SignalInfo>& signals, std::uint32_t signal) {
  if (signal >= signals.size()) {
    throw std::out_of_range("TraceRecorder: undeclared signal index");
  }
  return signals[signal];
}

void require_kind(const SignalInfo& info, bool ok, const char* what) {
  if (!ok) {
    throw std::invalid_argument(std::string("TraceRecorder: ") + what + " on signal " + info.name);
  }
}

const char* kind_name(SignalKind k) {
  switch (k) {
  case SignalKind::Wire:
    return "wire";
  case SignalKind::Integer:
    return "integer";
  case SignalKind::Real:
    return "real";
  }
  return "?";
}

std::string real_bits(double v) {
  constexpr char hex[] = "0123456789abcdef";
  const auto bits = std::bit_cast<std::uint64_t>(v);
  std::string s = "r";
  for (int i = 15; i >= 0; --i) s.push_back(hex[(bits >> (4 * i)) & 0xFU]);
  return s;
}

} // namespace

std::uint32_t TraceRecorder::declare(std::string_view name, SignalKind kind, std::uint8_t width) {
  if (kind == SignalKind::Wire) width = 1;
  if (kind == SignalKind::Real) width = 64;
  if (kind == SignalKind::Integer && (width == 0 || width > 64)) {
    throw std::invalid_argument("TraceRecorder: integer width must be 1..64");
  }
  if (auto it = index_.find(name); it != index_.end()) {
    const SignalInfo& info = signals_[it->second];
    if (info.kind != kind || info.width != width) {
      throw std::invalid_argument("TraceRecorder: " + info.name + " declared again with another kind");
    }
    return it->second;
  }
  const auto index = static_cast<std::uint32_t>(signals_.size());
  signals_.push_back(SignalInfo{std::string(name), kind, width});
  index_.emplace(std::string(name), index);
  return index;
}

void TraceRecorder::set_initial(std::uint32_t signal, std::int64_t v) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind != SignalKind::Real, "set_initial (use set_initial_real)");
  signals_[signal].has_initial = true;
  signals_[signal].initial = v;
}

void TraceRecorder::set_initial_real(std::uint32_t signal, double v) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind == SignalKind::Real, "set_initial_real");
  signals_[signal].has_initial = true;
  signals_[signal].initial_real = v;
}

void TraceRecorder::edge(std::uint32_t signal, const Edge& e) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind == SignalKind::Wire, "edge");
  samples_.push_back(TraceSample{e.time, signal, is_high(e.level) ? 1 : 0, 0.0});
}

void TraceRecorder::value(std::uint32_t signal, Nanos t, std::int64_t v) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind != SignalKind::Real, "value (use real)");
  samples_.push_back(TraceSample{t, signal, v, 0.0});
}

void TraceRecorder::real(std::uint32_t signal, Nanos t, double v) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind == SignalKind::Real, "real");
  samples_.push_back(TraceSample{t, signal, 0, v});
}

void TraceRecorder::can(std::string_view bus, Nanos t, const CanFrame& frame) {
  can_.push_back(TraceCanFrame{t, std::string(bus), frame});
}

void TraceRecorder::serial(std::string_view link, SerialDirection dir, Nanos t, std::uint8_t byte) {
  serial_.push_back(TraceSerialByte{t, std::string(link), dir, byte});
}

std::int64_t TraceRecorder::find(std::string_view name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? -1 : static_cast<std::int64_t>(it->second);
}

std::vector<Edge> TraceRecorder::edges_of(std::string_view name) const {
  std::vector<Edge> edges;
  const std::int64_t index = find(name);
  if (index < 0 || signals_[static_cast<std::size_t>(index)].kind != SignalKind::Wire) {
    return edges;
  }
  for (const TraceSample& s : samples_) {
    if (s.signal == static_cast<std::uint32_t>(index)) {
      edges.push_back(Edge{s.time, level_of(s.value != 0)});
    }
  }
  // Recorded in the order they happened, which is time order on a scheduler; a stable sort
  // keeps that order for equal times and guards hand-fed traces.
  std::stable_sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.time < b.time; });
  return edges;
}

namespace {

// Emits the canonical serialisation (documented at canonical_text() in trace.hpp) one record
// at a time, so hashing a long run never holds the whole text.
template <typename Sink> void emit_canonical(const TraceRecorder& t, Sink&& sink) {
  std::string line = "hilrig-trace 1\n";
  sink(line);
  const std::vector<SignalInfo>& signals = t.signals();
  for (std::size_t i = 0; i < signals.size(); ++i) {
    const SignalInfo& s = signals[i];
    line = "signal " + std::to_string(i) + ' ' + s.name + ' ' + kind_name(s.kind) + ' ' +
           std::to_string(s.width) + ' ';
    if (!s.has_initial) {
      line += 'x';
    } else if (s.kind == SignalKind::Real) {
      line += real_bits(s.initial_real);
    } else {
      line += std::to_string(s.initial);
    }
    line += '\n';
    sink(line);
  }
  for (const TraceSample& s : t.samples()) {
    line = "sample " + std::to_string(s.time.count()) + ' ' + std::to_string(s.signal) + ' ';
    line += signals[s.signal].kind == SignalKind::Real ? real_bits(s.real) : std::to_string(s.value);
    line += '\n';
    sink(line);
  }
  for (const TraceCanFrame& f : t.can_frames()) {
    line = "can " + std::to_string(f.time.count()) + ' ' + f.bus + ' ' + candump_frame_text(f.frame) + '\n';
    sink(line);
  }
  constexpr char hex[] = "0123456789abcdef";
  for (const TraceSerialByte& b : t.serial_bytes()) {
    line = "serial " + std::to_string(b.time.count()) + ' ' + b.link + ' ' +
           (b.direction == SerialDirection::AtoB ? "ab " : "ba ");
    line.push_back(hex[b.byte >> 4]);
    line.push_back(hex[b.byte & 0xFU]);
    line += '\n';
    sink(line);
  }
}

} // namespace

std::string TraceRecorder::canonical_text() const {
  std::string out;
  emit_canonical(*this, [&out](const std::string& line) { out += line; });
  return out;
}

std::uint64_t TraceRecorder::content_hash() const {
  std::uint64_t h = 0xcbf29ce484222325ULL; // FNV-1a 64 offset basis
  emit_canonical(*this, [&h](const std::string& line) {
    for (const char c : line) {
      h ^= static_cast<std::uint8_t>(c);
      h *= 0x100000001b3ULL; // FNV 64 prime
    }
  });
  return h;
}

} // namespace hilrig
