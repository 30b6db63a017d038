#pragma once
// The trace recorder: takes every edge, CAN frame, serial byte and named value with its
// timestamp, in the order they happen. Writers turn it into a VCD file (GTKWave,
// PulseView) and a candump-format CAN log; content_hash() fingerprints it so two runs
// can be compared byte for byte.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/can_frame.hpp"
#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig {

enum class SignalKind : std::uint8_t {
  Wire,    // a digital line (1 bit)
  Integer, // a multi-bit value (counts, register words), up to 64 bits
  Real,    // an analog value
};

struct SignalInfo {
  std::string name; // hierarchical with '.', e.g. "rig.enc.A" or "dut.ls1"
  SignalKind kind = SignalKind::Wire;
  std::uint8_t width = 1; // bits, for Integer
  // The value before the first sample (written in the VCD's $dumpvars); unknown ('x')
  // until set_initial() is called.
  bool has_initial = false;
  std::int64_t initial = 0;  // Wire, Integer
  double initial_real = 0.0; // Real
};

// What a run holds in memory before its trace spills (spill_beyond): 65,536 samples, 2 MiB,
// reserved when the limit is set, so the held samples never move and a run's memory does not
// grow with its length (bench figure 5). Measured 2026-11-27 against 4, 8 and 16 MiB (and 48
// MiB grown by doubling): more held means fewer instructions (less to encode and read back)
// but more pages first touched, and a page fault costs 10-40 us of system CPU on the VM the
// figures come from; the bench press and pls2700_update_2741 took the least CPU at 2 MiB
// (docs/PERFORMANCE.md, "The kernel's share"). A debounce check's probe runs, one per probe
// thread at once, hold the same.
inline constexpr std::size_t kTraceHeldSamples = std::size_t{1} << 16;

enum class SerialDirection : std::uint8_t { AtoB, BtoA };

struct TraceSample {
  Nanos time;
  std::uint32_t signal; // index into signals()
  std::int64_t value;   // Wire: 0/1; Integer: the value
  double real;          // Real only
};

struct TraceCanFrame {
  Nanos time; // end of frame
  std::string bus;
  CanFrame frame;
};

struct TraceSerialByte {
  Nanos time; // end of stop bit
  std::string link;
  SerialDirection direction;
  std::uint8_t byte;
};

class TraceRecorder {
public:
  // Declares a signal; declaring the same name twice returns the same index.
  // Declaring it again with another kind or width throws std::invalid_argument.
  std::uint32_t declare(std::string_view name, SignalKind kind = SignalKind::Wire, std::uint8_t width = 1);
  // The value a signal has before its first sample (e.g. a line's initial level).
  void set_initial(std::uint32_t signal, std::int64_t v);
  void set_initial_real(std::uint32_t signal, double v);

  void edge(std::uint32_t signal, const Edge& e);
  // Inline: a long run records millions (the shaft's count and position at every encoder edge).
  void value(std::uint32_t signal, Nanos t, std::int64_t v) {
    if (signal >= signals_.size() || signals_[signal].kind == SignalKind::Real) value_refused(signal);
    record(TraceSample{t, signal, v, 0.0});
  }
  void real(std::uint32_t signal, Nanos t, double v);
  void can(std::string_view bus, Nanos t, const CanFrame& frame);
  void serial(std::string_view link, SerialDirection dir, Nanos t, std::uint8_t byte);

  // Long runs: once `limit` samples are held in memory, they are moved to an anonymous
  // temporary file (in TMPDIR, else /tmp; gone when the recorder is), a few bytes a sample
  // (core/trace_spill.hpp), so a run's memory does not grow with its length. Every reader below
  // sees spilled samples as if they were still held, decoded a chunk at a time. The memory held
  // is the limit's, reserved here (pages a short run never fills cost nothing), and spilling
  // or reading back takes the buffers of one block (kSpillBlockSamples, ~1.6 MiB each). Throws
  // std::runtime_error when the file cannot be created, written or read back. (The recorder
  // owns the file: it moves, it is not copied.)
  void spill_beyond(std::size_t limit);
  // The limit spill_beyond() set (0: never spills).
  [[nodiscard]] std::size_t spill_limit() const { return spill_limit_; }

  [[nodiscard]] const std::vector<SignalInfo>& signals() const { return signals_; }
  // The samples still held in memory: all of them unless spill_beyond() moved some out.
  [[nodiscard]] const std::vector<TraceSample>& samples() const { return samples_; }
  // Every sample recorded, spilled or held.
  [[nodiscard]] std::size_t sample_count() const { return spilled_ + samples_.size(); }
  // Whether every sample was recorded at or after the time of the one before it (as a
  // scheduler records them); kept as they come, so no reader needs a pass to find out.
  [[nodiscard]] bool in_time_order() const { return in_time_order_; }
  // The latest time of any sample recorded, spilled or held (Nanos::min() before the first):
  // kept as they come, so finding a run's end reads nothing back.
  [[nodiscard]] Nanos latest_sample_time() const { return latest_time_; }
  // Calls `chunk` with the samples from index `from` on, in record order, a span at a time.
  using SampleChunk = std::function<void(std::span<const TraceSample>)>;
  void visit_samples(std::size_t from, const SampleChunk& chunk) const;
  // The same, until `chunk` returns false: no later chunk is decoded or read back.
  using SampleChunkWhile = std::function<bool(std::span<const TraceSample>)>;
  void visit_samples_while(std::size_t from, const SampleChunkWhile& chunk) const;
  [[nodiscard]] const std::vector<TraceCanFrame>& can_frames() const { return can_; }
  [[nodiscard]] const std::vector<TraceSerialByte>& serial_bytes() const { return serial_; }
  // Keeps the samples of the Wire signals of these names (declared now or later) as edges in
  // memory as they are recorded, so edges_of() asking only for them reads no sample back (a
  // spilled run's edges_of was a pass decoding every sample). Only before the first sample:
  // called later it keeps nothing (edges_of then reads the samples, as it does for a name not
  // kept).
  void keep_edges_of(std::span<const std::string> names);
  // Edges of one Wire signal, in time order.
  [[nodiscard]] std::vector<Edge> edges_of(std::string_view name) const;
  // The same for several signals in one pass over the samples; every name is a key of the
  // result (empty for a name that is not a declared Wire).
  [[nodiscard]] std::map<std::string, std::vector<Edge>, std::less<>>
  edges_of(std::span<const std::string> names) const;
  [[nodiscard]] std::int64_t find(std::string_view name) const; // -1 when absent

  // FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3) over the bytes of
  // canonical_text(): equal hashes mean equal recordings, in the same order.
  [[nodiscard]] std::uint64_t content_hash() const;
  // The canonical serialisation, version 1: ASCII, one record a line, each ending in '\n':
  //   hilrig-trace 1
  //   signal <index> <name> <wire|integer|real> <width> <initial|x>  (declaration order)
  //   sample <time_ns> <index> <value>                                (record order)
  //   can <time_ns> <bus> <candump frame text, e.g. 123##1DEADBEEF>   (record order)
  //   serial <time_ns> <link> <ab|ba> <byte, 2 lowercase hex digits>  (record order)
  // Integers in decimal; a real is 'r' and the 16 lowercase hex digits of its IEEE-754 bits,
  // so the text is exact and locale-free. Diff two runs' texts to find where they part.
  [[nodiscard]] std::string canonical_text() const;

private:
  // Records one sample; the growth and the spill out of line.
  void record(const TraceSample& s) {
    in_time_order_ = in_time_order_ && s.time >= last_time_;
    last_time_ = s.time;
    if (s.time > latest_time_) latest_time_ = s.time;
    if (keeping_ && kept_of_[s.signal] != 0) keep(s);
    if (samples_.size() == samples_.capacity()) grow();
    samples_.push_back(s);
    if (samples_.size() >= spill_at_) spill();
  }
  void grow();
  void keep(const TraceSample& s);
  [[noreturn]] void value_refused(std::uint32_t signal) const;
  void spill();

  struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  // The most samples one block of the spill file holds (spill() writes what is held as blocks
  // of at most this many): encoding or reading back a block takes ~1.6 MiB at most.
  static constexpr std::size_t kSpillBlockSamples = std::size_t{1} << 16;
  // A block of samples in the file: where its bytes start, and its first sample's index.
  struct SpillBlock {
    std::size_t first = 0;
    std::uint64_t offset = 0;
  };

  std::map<std::string, std::uint32_t, std::less<>> index_;
  std::vector<SignalInfo> signals_;
  std::vector<TraceSample> samples_;
  bool in_time_order_ = true;
  Nanos last_time_ = Nanos::min();
  Nanos latest_time_ = Nanos::min();
  std::size_t spill_limit_ = 0;                         // 0: never spill
  std::size_t spill_at_ = static_cast<std::size_t>(-1); // spill_limit_, or never
  std::size_t spilled_ = 0;                             // samples in spill_file_, the oldest first
  std::vector<SpillBlock> spill_blocks_;
  std::uint64_t spill_bytes_ = 0; // the file's length
  // A block's bytes on their way to the file: room for the worst case, only what is written
  // touched (not a zero-filled vector).
  std::unique_ptr<std::uint8_t[]> spill_buffer_;
  std::size_t spill_buffer_size_ = 0;
  std::unique_ptr<std::FILE, CloseFile> spill_file_;
  // keep_edges_of: the names, and per signal 1 + its index in kept_ (0: not kept).
  std::vector<std::string> keep_names_;
  bool keeping_ = false;
  std::vector<std::uint32_t> kept_of_;
  std::vector<std::vector<Edge>> kept_;
  std::vector<TraceCanFrame> can_;
  std::vector<TraceSerialByte> serial_;
};

// VCD (IEEE 1364 §18): 1 ns timescale, a $scope per dotted name component; wires as 1-bit
// "wire" vars, integers as "integer" vars of their width (b..., two's complement), reals as
// "real" (r..., shortest round-trip decimal); $dumpvars at #0 holds each signal's initial
// value (x when unset; 0 for a real); then the samples with times ascending (stable for
// equal times). The date comment, when given, is the only thing not fixed by the trace.
// Negative times throw std::invalid_argument. For long runs see core/vcd_stream.hpp.
// `overlay`: more samples of the trace's signals, known only after the run (e.g. the windows
// the checks judged), merged in time order after the trace's own samples of the same time.
void write_vcd(const TraceRecorder& trace, std::ostream& out, std::string_view date_comment = "",
               std::span<const TraceSample> overlay = {});
// candump -l format: "(seconds.micros) bus ID#DATA" / "ID##FDATA" for FD (see core/candump.hpp).
struct CandumpOptions {
  // Adds CANFD_FDF to the FD flags nibble, as Linux 6.0+ kernels report received FD frames.
  bool fdf_flag = false;
  // Added to every timestamp. Virtual time starts at 0, but log2asc (can-utils 2020.11) takes
  // any frame whose seconds are 0 for the start of a new log: give it a wall-clock epoch.
  Nanos epoch{0};
};
void write_candump(const TraceRecorder& trace, std::ostream& out, const CandumpOptions& options = {});

} // namespace hilrig
