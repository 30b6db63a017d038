#pragma once
// The encoding of a long trace's samples once they leave memory (TraceRecorder::spill_beyond):
// a block of samples as bytes, self-contained (decoding it needs only the signals' kinds), so
// a reader can start at any block. Per sample:
//   varint(zigzag(time - previous sample's time))      (the first against 0; any order)
//   varint(signal index)
//   Real: the 8 bytes of the double's IEEE-754 bits, little-endian (exact, NaN payloads too)
//   else: varint(zigzag(value - the signal's previous value in the block))  (the first against 0)
// Deltas wrap modulo 2^64, so every int64 round-trips. An encoder edge is ~4 bytes (time delta
// 2, index 1, count step 1) instead of a 32-byte TraceSample.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/trace.hpp"

namespace hilrig::trace_spill {

// The most bytes one sample takes: a 10-byte time delta, a 5-byte index, a 10-byte value.
inline constexpr std::size_t kMaxSampleBytes = 10 + 5 + 10;

// Encodes `samples` into `out`, which must hold samples.size() * kMaxSampleBytes, and returns
// the block's length. `signals` holds every signal the samples name.
std::size_t encode(std::span<const TraceSample> samples, std::span<const SignalInfo> signals,
                   std::span<std::uint8_t> out);

// Reads a block written by encode(), a chunk of samples at a time.
class BlockDecoder {
public:
  BlockDecoder(std::span<const std::uint8_t> block, std::span<const SignalInfo> signals);
  // Decodes up to out.size() samples into `out`; returns how many (0: the block is done).
  // Throws std::runtime_error on a block that ends inside a sample or names an unknown signal.
  std::size_t next(std::span<TraceSample> out);

private:
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
  std::span<const SignalInfo> signals_;
  std::uint64_t time_ = 0;
  std::vector<std::uint64_t> last_; // per signal: its previous value in the block
  std::vector<std::uint8_t> real_;  // per signal: 1 for a Real (its kind, packed)
};

} // namespace hilrig::trace_spill
