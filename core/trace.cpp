#include "core/trace.hpp"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/candump.hpp"
#include "core/trace_spill.hpp"

namespace hilrig {
namespace {

const SignalInfo& checked(const std::vector<SignalInfo>& signals, std::uint32_t signal) {
  if (signal >= signals.size()) {
    throw std::out_of_range("TraceRecorder: undeclared signal index");
  }
  return signals[signal];
}

// An anonymous file in TMPDIR (else /tmp), gone once closed. Not std::tmpfile: glibc's
// ignores TMPDIR, and where /tmp is read-only (the RT VM lane's guest shares the host's root
// read-only and points TMPDIR at its writable output) a long run could not spill.
std::FILE* anonymous_temporary_file() {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) {
    throw std::runtime_error(
        "TraceRecorder: cannot create a temporary file to spill to: no temporary directory "
        "(TMPDIR: " +
        ec.message() + ")");
  }
  std::string name = (dir / "hilrig-trace-XXXXXX").string();
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    throw std::runtime_error("TraceRecorder: cannot create a temporary file to spill to in " + dir.string() +
                             ": " + std::strerror(errno));
  }
  ::unlink(name.c_str());
  std::FILE* f = ::fdopen(fd, "w+b");
  if (f == nullptr) {
    ::close(fd);
    throw std::runtime_error("TraceRecorder: cannot open the spill file: " +
                             std::string(std::strerror(errno)));
  }
  return f;
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
  kept_of_.push_back(0);
  if (keeping_ && kind == SignalKind::Wire &&
      std::find(keep_names_.begin(), keep_names_.end(), name) != keep_names_.end()) {
    kept_.emplace_back();
    kept_of_.back() = static_cast<std::uint32_t>(kept_.size());
  }
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
  record(TraceSample{e.time, signal, is_high(e.level) ? 1 : 0, 0.0});
}

void TraceRecorder::value_refused(std::uint32_t signal) const {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind != SignalKind::Real, "value (use real)");
  throw std::logic_error("TraceRecorder::value: refused a valid sample"); // not reached
}

void TraceRecorder::real(std::uint32_t signal, Nanos t, double v) {
  const SignalInfo& info = checked(signals_, signal);
  require_kind(info, info.kind == SignalKind::Real, "real");
  record(TraceSample{t, signal, 0, v});
}

void TraceRecorder::grow() {
  // Only a recorder without a limit grows here (spill_beyond reserves the limit): by doubling.
  samples_.reserve(std::max<std::size_t>(1024, 2 * samples_.capacity()));
}

void TraceRecorder::spill_beyond(std::size_t limit) {
  spill_limit_ = limit;
  // Reserved once: untouched pages cost nothing, and filled ones are never copied to a larger
  // block (whose pages would fault again while the smaller one is still held).
  if (limit != 0) samples_.reserve(limit);
  spill_at_ = limit != 0 ? limit : static_cast<std::size_t>(-1);
  if (limit != 0 && samples_.size() >= limit) spill();
}

namespace {

[[noreturn]] void spill_failed(const char* what) {
  throw std::runtime_error(std::string("TraceRecorder: cannot ") + what +
                           " the spill file: " + std::strerror(errno));
}

} // namespace

void TraceRecorder::spill() {
  if (!spill_file_) spill_file_.reset(anonymous_temporary_file());
  // In blocks of at most kSpillBlockSamples: the buffer a block is encoded into, and the one
  // visit_samples() reads a block back into, stay small however many samples are held.
  const std::size_t most = std::min(samples_.size(), kSpillBlockSamples);
  if (spill_buffer_size_ < most * trace_spill::kMaxSampleBytes) {
    spill_buffer_size_ = most * trace_spill::kMaxSampleBytes;
    spill_buffer_ = std::make_unique_for_overwrite<std::uint8_t[]>(spill_buffer_size_);
  }
  const std::span<std::uint8_t> buffer(spill_buffer_.get(), spill_buffer_size_);
  const int fd = fileno(spill_file_.get());
  for (std::size_t from = 0; from < samples_.size(); from += kSpillBlockSamples) {
    const std::span<const TraceSample> part = std::span<const TraceSample>(samples_).subspan(
        from, std::min(kSpillBlockSamples, samples_.size() - from));
    const std::span<const std::uint8_t> block = buffer.first(trace_spill::encode(part, signals_, buffer));
    // Written whole at the file's end, unbuffered: each block is read back with pread().
    for (std::size_t done = 0; done < block.size();) {
      const ssize_t n =
          ::pwrite(fd, block.data() + done, block.size() - done, static_cast<off_t>(spill_bytes_ + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) spill_failed("write");
      done += static_cast<std::size_t>(n);
    }
    spill_blocks_.push_back(SpillBlock{spilled_ + from, spill_bytes_});
    spill_bytes_ += block.size();
  }
  spilled_ += samples_.size();
  samples_.clear(); // keeps its capacity: the memory held stays at the limit
}

void TraceRecorder::visit_samples(std::size_t from, const SampleChunk& chunk) const {
  visit_samples_while(from, [&](std::span<const TraceSample> samples) {
    chunk(samples);
    return true;
  });
}

void TraceRecorder::visit_samples_while(std::size_t from, const SampleChunkWhile& chunk) const {
  if (from < spilled_) {
    // The block holding `from`, then each block after it, decoded a chunk at a time.
    auto block = std::upper_bound(spill_blocks_.begin(), spill_blocks_.end(), from,
                                  [](std::size_t i, const SpillBlock& b) { return i < b.first; }) -
                 1;
    const int fd = fileno(spill_file_.get());
    std::vector<std::uint8_t> bytes;
    std::vector<TraceSample> decoded(8192);
    for (; block != spill_blocks_.end(); ++block) {
      const auto next = block + 1;
      const std::uint64_t end = next == spill_blocks_.end() ? spill_bytes_ : next->offset;
      bytes.resize(static_cast<std::size_t>(end - block->offset));
      for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n =
            ::pread(fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(block->offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) spill_failed("read");
        done += static_cast<std::size_t>(n);
      }
      trace_spill::BlockDecoder decoder(bytes, signals_);
      std::size_t index = block->first;
      while (const std::size_t n = decoder.next(decoded)) {
        if (index + n > from) {
          const std::size_t skip = from > index ? from - index : 0;
          if (!chunk(std::span<const TraceSample>(decoded.data() + skip, n - skip))) return;
        }
        index += n;
      }
    }
    from = spilled_;
  }
  const std::size_t held = from - spilled_;
  if (held < samples_.size()) chunk(std::span<const TraceSample>(samples_).subspan(held));
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

void TraceRecorder::keep_edges_of(std::span<const std::string> names) {
  if (sample_count() != 0 || names.empty()) return;
  keeping_ = true;
  for (const std::string& name : names) {
    if (std::find(keep_names_.begin(), keep_names_.end(), name) != keep_names_.end()) continue;
    keep_names_.push_back(name);
    const std::int64_t index = find(name);
    if (index < 0 || signals_[static_cast<std::size_t>(index)].kind != SignalKind::Wire) continue;
    kept_.emplace_back();
    kept_of_[static_cast<std::size_t>(index)] = static_cast<std::uint32_t>(kept_.size());
  }
}

void TraceRecorder::keep(const TraceSample& s) {
  kept_[kept_of_[s.signal] - 1].push_back(Edge{s.time, level_of(s.value != 0)});
}

std::vector<Edge> TraceRecorder::edges_of(std::string_view name) const {
  const std::string names[] = {std::string(name)};
  return std::move(edges_of(names).begin()->second);
}

std::map<std::string, std::vector<Edge>, std::less<>>
TraceRecorder::edges_of(std::span<const std::string> names) const {
  std::map<std::string, std::vector<Edge>, std::less<>> out;
  // Per signal index: where its edges go (null for signals nobody asked for).
  std::vector<std::vector<Edge>*> wanted(signals_.size(), nullptr);
  bool any = false;
  bool all_kept = true;
  for (const std::string& name : names) {
    std::vector<Edge>& edges = out[name];
    const std::int64_t index = find(name);
    if (index < 0 || signals_[static_cast<std::size_t>(index)].kind != SignalKind::Wire) continue;
    wanted[static_cast<std::size_t>(index)] = &edges;
    any = true;
    all_kept = all_kept && kept_of_[static_cast<std::size_t>(index)] != 0;
  }
  if (!any) return out;
  if (all_kept) {
    // Kept as they were recorded: the samples the pass below would collect, in the same order.
    for (std::size_t i = 0; i < wanted.size(); ++i)
      if (wanted[i] != nullptr) *wanted[i] = kept_[kept_of_[i] - 1];
  } else {
    visit_samples(0, [&](std::span<const TraceSample> chunk) {
      for (const TraceSample& s : chunk) {
        if (std::vector<Edge>* edges = wanted[s.signal])
          edges->push_back(Edge{s.time, level_of(s.value != 0)});
      }
    });
  }
  // Recorded in the order they happened, which is time order on a scheduler; a stable sort
  // keeps that order for equal times and guards hand-fed traces.
  const auto by_time = [](const Edge& a, const Edge& b) { return a.time < b.time; };
  for (auto& [name, edges] : out) {
    if (!std::is_sorted(edges.begin(), edges.end(), by_time))
      std::stable_sort(edges.begin(), edges.end(), by_time);
  }
  return out;
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
  t.visit_samples(0, [&](std::span<const TraceSample> chunk) {
    for (const TraceSample& s : chunk) {
      line = "sample " + std::to_string(s.time.count()) + ' ' + std::to_string(s.signal) + ' ';
      line += signals[s.signal].kind == SignalKind::Real ? real_bits(s.real) : std::to_string(s.value);
      line += '\n';
      sink(line);
    }
  });
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
