#include "core/trace_spill.hpp"

#include <bit>
#include <stdexcept>

namespace hilrig::trace_spill {
namespace {

[[gnu::always_inline]] inline std::uint8_t* put_varint(std::uint8_t* out, std::uint64_t v) {
  if (v < 0x80U) { // most of them: an index, a level, a count step
    *out++ = static_cast<std::uint8_t>(v);
    return out;
  }
  while (v >= 0x80U) {
    *out++ = static_cast<std::uint8_t>(v | 0x80U);
    v >>= 7U;
  }
  *out++ = static_cast<std::uint8_t>(v);
  return out;
}

// A signed difference (taken modulo 2^64) as an unsigned number small for small magnitudes.
std::uint64_t zigzag(std::uint64_t delta) { return (delta << 1U) ^ (0U - (delta >> 63U)); }

std::uint64_t unzigzag(std::uint64_t z) { return (z >> 1U) ^ (0U - (z & 1U)); }

[[noreturn]] void corrupt() { throw std::runtime_error("TraceRecorder: the spill file is corrupt"); }

// Reads a varint at `at`, which may run to `end` (checked only when `Checked`: far from the
// block's end no sample can cross it, and most of a block is decoded unchecked).
template <bool Checked>
[[gnu::always_inline]] inline std::uint64_t get_varint(const std::uint8_t*& at, const std::uint8_t* end) {
  if (Checked && at == end) corrupt();
  if (*at < 0x80U) return *at++;   // most of them: an index, a level, a count step
  if (!Checked && at[1] < 0x80U) { // two bytes: a time step under 8 us (an encoder edge)
    const std::uint64_t v = (at[0] & 0x7FU) | (static_cast<std::uint64_t>(at[1]) << 7U);
    at += 2;
    return v;
  }
  std::uint64_t v = 0;
  for (unsigned shift = 0; shift < 64; shift += 7) {
    if (Checked && at == end) corrupt();
    const std::uint8_t b = *at++;
    v |= static_cast<std::uint64_t>(b & 0x7FU) << shift;
    if ((b & 0x80U) == 0) return v;
  }
  corrupt();
}

} // namespace

std::size_t encode(std::span<const TraceSample> samples, std::span<const SignalInfo> signals,
                   std::span<std::uint8_t> out) {
  if (out.size() < samples.size() * kMaxSampleBytes)
    throw std::logic_error("trace_spill::encode: out too small");
  std::vector<std::uint64_t> last(signals.size(), 0);
  std::vector<std::uint8_t> real(signals.size(), 0);
  for (std::size_t i = 0; i < signals.size(); ++i) real[i] = signals[i].kind == SignalKind::Real ? 1 : 0;
  std::uint64_t time = 0;
  std::uint8_t* const start = out.data();
  std::uint8_t* at = start;
  for (const TraceSample& s : samples) {
    const auto t = static_cast<std::uint64_t>(s.time.count());
    at = put_varint(at, zigzag(t - time));
    time = t;
    at = put_varint(at, s.signal);
    if (real[s.signal] != 0) {
      const auto bits = std::bit_cast<std::uint64_t>(s.real);
      for (unsigned i = 0; i < 64; i += 8) *at++ = static_cast<std::uint8_t>(bits >> i);
    } else {
      const auto v = static_cast<std::uint64_t>(s.value);
      at = put_varint(at, zigzag(v - last[s.signal]));
      last[s.signal] = v;
    }
  }
  return static_cast<std::size_t>(at - start);
}

BlockDecoder::BlockDecoder(std::span<const std::uint8_t> block, std::span<const SignalInfo> signals)
    : bytes_(block), signals_(signals), last_(signals.size(), 0), real_(signals.size(), 0) {
  for (std::size_t i = 0; i < signals.size(); ++i) real_[i] = signals[i].kind == SignalKind::Real ? 1 : 0;
}

std::size_t BlockDecoder::next(std::span<TraceSample> out) {
  const std::uint8_t* at = bytes_.data() + at_;
  const std::uint8_t* const end = bytes_.data() + bytes_.size();
  // Samples wholly before `safe` cannot run past the end: decoded without bounds checks.
  const std::uint8_t* const safe = bytes_.size() > kMaxSampleBytes ? end - kMaxSampleBytes : bytes_.data();
  // Locals, not members: the compiler need not reload them after each store to `out`.
  std::uint64_t time = time_;
  std::uint64_t* const last = last_.data();
  const std::uint8_t* const real = real_.data();
  const std::size_t declared = signals_.size();
  const auto one = [&]<bool Checked>(TraceSample& s) {
    time += unzigzag(get_varint<Checked>(at, end));
    const std::uint64_t signal = get_varint<Checked>(at, end);
    if (signal >= declared) corrupt();
    if (real[signal] != 0) {
      if (Checked && end - at < 8) corrupt();
      std::uint64_t bits = 0;
      for (unsigned i = 0; i < 64; i += 8) bits |= static_cast<std::uint64_t>(*at++) << i;
      s = TraceSample{Nanos{static_cast<std::int64_t>(time)}, static_cast<std::uint32_t>(signal), 0,
                      std::bit_cast<double>(bits)};
    } else {
      const std::uint64_t v = last[signal] + unzigzag(get_varint<Checked>(at, end));
      last[signal] = v;
      s = TraceSample{Nanos{static_cast<std::int64_t>(time)}, static_cast<std::uint32_t>(signal),
                      static_cast<std::int64_t>(v), 0.0};
    }
  };
  std::size_t n = 0;
  for (; n < out.size() && at < safe; ++n) one.template operator()<false>(out[n]);
  for (; n < out.size() && at < end; ++n) one.template operator()<true>(out[n]);
  at_ = static_cast<std::size_t>(at - bytes_.data());
  time_ = time;
  return n;
}

} // namespace hilrig::trace_spill
