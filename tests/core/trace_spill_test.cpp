#include "core/trace_spill.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/trace.hpp"
#include "core/vcd_stream.hpp"

using namespace hilrig;
using namespace hilrig::literals;

namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();

// A sample as the recorder keeps it, compared field by field (reals by their bits, so NaN
// payloads and -0.0 count).
struct Plain {
  std::int64_t time;
  std::uint32_t signal;
  std::int64_t value;
  std::uint64_t real_bits;
  friend bool operator==(const Plain&, const Plain&) = default;
};

Plain plain(const TraceSample& s) {
  return {s.time.count(), s.signal, s.value, std::bit_cast<std::uint64_t>(s.real)};
}

// Signals of every kind: two wires, integers of width 1, 16 and 64, two reals.
std::vector<std::uint32_t> declare_all(TraceRecorder& t) {
  return {t.declare("w.a"),
          t.declare("w.b"),
          t.declare("n.one", SignalKind::Integer, 1),
          t.declare("n.count", SignalKind::Integer, 16),
          t.declare("n.wide", SignalKind::Integer, 64),
          t.declare("an.u", SignalKind::Real),
          t.declare("an.v", SignalKind::Real)};
}

// Seeded random samples recorded into `t` (declared by declare_all) through its public calls,
// returned as recorded. `ordered`: times never go back; otherwise they jump both ways, to the
// int64 extremes too. Values: small steps both ways, random 64-bit words, the extremes; reals:
// ordinary numbers, +-0, +-inf, NaNs with payloads, the smallest subnormal, the largest double.
std::vector<Plain> record_random(TraceRecorder& t, const std::vector<std::uint32_t>& signals,
                                 std::uint64_t seed, int count, bool ordered) {
  std::mt19937_64 rng(seed);
  const std::int64_t extremes[] = {0, -1, 1, kMin, kMax, kMin + 1, kMax - 1, 255, -256};
  const double reals[] = {0.0,
                          -0.0,
                          1.25,
                          -3e-300,
                          std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN(),
                          std::bit_cast<double>(std::uint64_t{0x7FF0000000000001}), // signalling NaN
                          std::bit_cast<double>(std::uint64_t{0xFFF8DEADBEEF0001}), // negative NaN, payload
                          std::numeric_limits<double>::denorm_min(),
                          std::numeric_limits<double>::max()};
  std::vector<Plain> out;
  std::int64_t now = 0;
  std::int64_t count16 = 0;
  for (int i = 0; i < count; ++i) {
    if (ordered) {
      if (rng() % 2 == 0) now += static_cast<std::int64_t>(rng() % 20000);
    } else {
      switch (rng() % 4) {
      case 0:
        now = extremes[rng() % std::size(extremes)];
        break;
      case 1:
        // Back in time, wrapping as the encoding's deltas do (now may be the most negative time).
        now = static_cast<std::int64_t>(static_cast<std::uint64_t>(now) - rng() % 20000);
        break;
      default:
        now = static_cast<std::int64_t>(rng()) >> (rng() % 64);
        break;
      }
    }
    const std::uint32_t s = signals[rng() % signals.size()];
    switch (t.signals()[s].kind) {
    case SignalKind::Wire: {
      const bool high = rng() % 2 == 0;
      t.edge(s, Edge{Nanos{now}, level_of(high)});
      out.push_back({now, s, high ? 1 : 0, 0});
      break;
    }
    case SignalKind::Integer: {
      std::int64_t v = 0;
      switch (rng() % 3) {
      case 0:
        v = count16 += (rng() % 2 == 0 ? 1 : -1); // a count stepping both ways
        break;
      case 1:
        v = extremes[rng() % std::size(extremes)];
        break;
      default:
        v = static_cast<std::int64_t>(rng());
        break;
      }
      t.value(s, Nanos{now}, v);
      out.push_back({now, s, v, 0});
      break;
    }
    case SignalKind::Real: {
      const double v = rng() % 2 == 0 ? reals[rng() % std::size(reals)]
                                      : std::ldexp(static_cast<double>(rng() % 2000001) - 1e6,
                                                   static_cast<int>(rng() % 200) - 100);
      t.real(s, Nanos{now}, v);
      out.push_back({now, s, 0, std::bit_cast<std::uint64_t>(v)});
      break;
    }
    }
  }
  return out;
}

std::vector<Plain> read_back(const TraceRecorder& t, std::size_t from = 0) {
  std::vector<Plain> out;
  t.visit_samples(from, [&](std::span<const TraceSample> chunk) {
    for (const TraceSample& s : chunk) out.push_back(plain(s));
  });
  return out;
}

std::string vcd_with_overlay(const TraceRecorder& t, std::span<const TraceSample> overlay = {}) {
  std::ostringstream out;
  write_vcd(t, out, "", overlay);
  return out.str();
}

} // namespace

// The block encoding alone: every kind of sample, every value and time the recorder can hold,
// read back equal, whatever the chunk size the reader asks for.
TEST(TraceSpill, BlockRoundTripsEverySampleKindAndExtreme) {
  for (const std::uint64_t seed : {1U, 2U, 3U, 4U, 5U}) {
    TraceRecorder t;
    const std::vector<std::uint32_t> signals = declare_all(t);
    record_random(t, signals, seed, 3000, seed % 2 == 0);
    const std::vector<TraceSample>& samples = t.samples();
    std::vector<std::uint8_t> bytes(samples.size() * trace_spill::kMaxSampleBytes);
    bytes.resize(trace_spill::encode(samples, t.signals(), bytes));
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{4096}}) {
      trace_spill::BlockDecoder decoder(bytes, t.signals());
      std::vector<TraceSample> buffer(chunk);
      std::vector<Plain> got;
      while (const std::size_t n = decoder.next(buffer))
        for (std::size_t i = 0; i < n; ++i) got.push_back(plain(buffer[i]));
      ASSERT_EQ(got.size(), samples.size()) << "seed " << seed << " chunk " << chunk;
      for (std::size_t i = 0; i < got.size(); ++i)
        ASSERT_EQ(got[i], plain(samples[i])) << "seed " << seed << " sample " << i;
    }
  }
}

// The sizes the format (core/trace_spill.hpp) gives an encoder at 1,800 RPM with 1,024 lines:
// an edge every 8,138 ns (zigzag 16,276 < 2^14: a 2-byte varint), index 1 byte, level step
// 1 byte = 4 bytes; the count at the same time: 0 delta, index, +1 step = 3 bytes.
TEST(TraceSpill, AnEncoderEdgeAndItsCountTakeSevenBytes) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("enc.A");
  const std::uint32_t n = t.declare("dut.count", SignalKind::Integer, 16);
  std::vector<TraceSample> samples;
  for (std::int64_t k = 1; k <= 1000; ++k) {
    samples.push_back(TraceSample{Nanos{8138 * k}, a, k % 2, 0.0});
    samples.push_back(TraceSample{Nanos{8138 * k}, n, k, 0.0});
  }
  std::vector<std::uint8_t> scratch(samples.size() * trace_spill::kMaxSampleBytes);
  // The first edge's time (8,138 from 0) is the same 2 bytes as every later delta.
  EXPECT_EQ(trace_spill::encode(samples, t.signals(), scratch), 1000U * 7U);
  // A real is its 8 raw bytes after the time delta and the index.
  const std::uint32_t v = t.declare("an.v", SignalKind::Real);
  const TraceSample real[] = {{Nanos{1}, v, 0, 0.5}};
  EXPECT_EQ(trace_spill::encode(real, t.signals(), scratch), 1U + 1U + 8U);
}

// Every varint length at its edges (1 to 10 bytes: 0x7F, 0x80, 0x3FFF, 0x4000, ... as a time step
// and as a value step), far from the block's end (decoded unchecked, the 2-byte case on its own
// path) and at it (checked), read back equal.
TEST(TraceSpill, VarintsOfEveryLengthRoundTripAtTheirEdges) {
  TraceRecorder t;
  const std::uint32_t n = t.declare("n", SignalKind::Integer, 64);
  const std::uint32_t w = t.declare("w");
  std::vector<TraceSample> samples;
  std::int64_t now = 0;
  std::int64_t value = 0;
  for (int round = 0; round < 3; ++round) {
    for (unsigned bits = 1; bits < 64; ++bits) {
      for (const std::uint64_t step : {(std::uint64_t{1} << bits) - 1U, std::uint64_t{1} << bits}) {
        // zigzag(d) = 2d for d >= 0: half the step gives a varint of exactly that many bits.
        const auto half = static_cast<std::int64_t>(step / 2);
        now += half;
        value += round == 1 ? -half : half;
        samples.push_back(TraceSample{Nanos{now}, n, value, 0.0});
        samples.push_back(TraceSample{Nanos{now}, w, value & 1, 0.0});
        // Both start again before the next step could overflow them (a step is at most 2^62).
        if (now > std::numeric_limits<std::int64_t>::max() / 4) now = 0;
        if (value > std::numeric_limits<std::int64_t>::max() / 4 ||
            value < std::numeric_limits<std::int64_t>::min() / 4)
          value = 0;
      }
    }
  }
  std::vector<std::uint8_t> bytes(samples.size() * trace_spill::kMaxSampleBytes);
  bytes.resize(trace_spill::encode(samples, t.signals(), bytes));
  for (const std::size_t chunk : {std::size_t{1}, std::size_t{64}, std::size_t{4096}}) {
    trace_spill::BlockDecoder decoder(bytes, t.signals());
    std::vector<TraceSample> buffer(chunk);
    std::vector<Plain> got;
    while (const std::size_t k = decoder.next(buffer))
      for (std::size_t i = 0; i < k; ++i) got.push_back(plain(buffer[i]));
    ASSERT_EQ(got.size(), samples.size()) << "chunk " << chunk;
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], plain(samples[i])) << "sample " << i;
  }
}

TEST(TraceSpill, ATruncatedBlockIsAnErrorNotASample) {
  TraceRecorder t;
  const std::uint32_t n = t.declare("n", SignalKind::Integer, 64);
  const std::uint32_t v = t.declare("v", SignalKind::Real);
  const TraceSample samples[] = {{Nanos{300}, n, kMin, 0.0}, {Nanos{400}, v, 0, 2.0}};
  std::vector<std::uint8_t> bytes(2 * trace_spill::kMaxSampleBytes);
  const std::size_t first = trace_spill::encode(std::span(samples).first(1), t.signals(), bytes);
  bytes.resize(trace_spill::encode(samples, t.signals(), bytes));
  for (std::size_t cut = 1; cut < bytes.size(); ++cut) {
    const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(cut));
    trace_spill::BlockDecoder decoder(part, t.signals());
    std::vector<TraceSample> buffer(4);
    // A cut between the two samples gives the first and then ends; any other cut throws.
    bool threw = false;
    try {
      while (decoder.next(buffer) != 0) {}
    } catch (const std::runtime_error&) {
      threw = true;
    }
    const bool between = cut == first;
    EXPECT_EQ(threw, !between) << "cut at " << cut;
  }
}

// Through the recorder: with spill limits from 1 sample up, the samples read back from any
// starting index are the ones recorded, in record order, spilled or held.
TEST(TraceSpill, RecorderReadsBackWhatWasRecordedAcrossTheSpillLimit) {
  for (const std::size_t limit : {std::size_t{1}, std::size_t{2}, std::size_t{13}, std::size_t{512}}) {
    for (const bool ordered : {true, false}) {
      TraceRecorder t;
      t.spill_beyond(limit);
      const std::vector<std::uint32_t> signals = declare_all(t);
      const std::vector<Plain> recorded =
          record_random(t, signals, limit * 2 + (ordered ? 1 : 0), 2000, ordered);
      ASSERT_EQ(t.sample_count(), recorded.size());
      EXPECT_LT(t.samples().size(), limit);
      EXPECT_EQ(read_back(t), recorded) << "limit " << limit;
      for (const std::size_t from :
           {std::size_t{1}, limit - 1, limit, limit + 1, std::size_t{1999}, std::size_t{2000}}) {
        const std::vector<Plain> tail(recorded.begin() + static_cast<std::ptrdiff_t>(from), recorded.end());
        EXPECT_EQ(read_back(t, from), tail) << "limit " << limit << " from " << from;
      }
    }
  }
}

// A reader that stops (visit_samples_while's chunk returns false) is handed no chunk after
// that one: what it saw is the recording's first samples, in order, and no more than the
// chunk it stopped in; one that never stops sees everything.
TEST(TraceSpill, AReaderThatStopsIsHandedNoMoreChunks) {
  for (const std::size_t limit : {std::size_t{0}, std::size_t{13}, std::size_t{512}}) {
    TraceRecorder t;
    if (limit > 0) t.spill_beyond(limit);
    const std::vector<std::uint32_t> signals = declare_all(t);
    const std::vector<Plain> recorded = record_random(t, signals, 11, 2000, true);
    for (const std::size_t stop_after :
         {std::size_t{1}, std::size_t{500}, std::size_t{1999}, std::size_t{5000}}) {
      std::vector<Plain> seen;
      std::size_t chunks_after_stop = 0;
      bool stopped = false;
      std::size_t last_chunk = 0;
      t.visit_samples_while(0, [&](std::span<const TraceSample> chunk) {
        if (stopped) ++chunks_after_stop;
        for (const TraceSample& s : chunk) seen.push_back(plain(s));
        last_chunk = chunk.size();
        stopped = seen.size() >= stop_after;
        return !stopped;
      });
      EXPECT_EQ(chunks_after_stop, 0U) << "limit " << limit << " stop " << stop_after;
      const std::size_t want = std::min(stop_after, recorded.size());
      ASSERT_GE(seen.size(), want);
      EXPECT_LT(seen.size() - want, std::max<std::size_t>(last_chunk, 1)) << "limit " << limit;
      EXPECT_EQ(seen, std::vector<Plain>(recorded.begin(),
                                         recorded.begin() + static_cast<std::ptrdiff_t>(seen.size())));
      if (limit == 13 && stop_after == 500) {
        EXPECT_LT(seen.size(), 520U); // blocks of 13 read back one by one
      }
    }
  }
}

// Samples recorded after the recorder was told to spill, and more after that: the limit set
// later spills what is held at once.
TEST(TraceSpill, ALimitSetLaterSpillsWhatIsHeld) {
  TraceRecorder t;
  const std::vector<std::uint32_t> signals = declare_all(t);
  std::vector<Plain> recorded = record_random(t, signals, 9, 300, true);
  t.spill_beyond(100);
  EXPECT_TRUE(t.samples().empty());
  const std::vector<Plain> more = record_random(t, signals, 10, 250, true);
  recorded.insert(recorded.end(), more.begin(), more.end());
  EXPECT_EQ(read_back(t), recorded);
}

// The latest sample time is known without reading the recording back: the greatest time read
// back, spilled or held, in or out of time order; Nanos::min() before the first sample.
TEST(TraceRecorder, KnowsItsLatestSampleTimeSpilledOrHeld) {
  for (const std::size_t limit : {std::size_t{0}, std::size_t{1}, std::size_t{13}})
    for (const bool ordered : {true, false}) {
      TraceRecorder t;
      if (limit > 0) t.spill_beyond(limit);
      const std::vector<std::uint32_t> signals = declare_all(t);
      EXPECT_EQ(t.latest_sample_time(), Nanos::min());
      (void)record_random(t, signals, 7, 200, ordered);
      Nanos latest = Nanos::min();
      t.visit_samples(0, [&](std::span<const TraceSample> chunk) {
        for (const TraceSample& s : chunk) latest = std::max(latest, s.time);
      });
      EXPECT_EQ(t.latest_sample_time(), latest) << "limit " << limit << " ordered " << ordered;
    }
  TraceRecorder t;
  const std::uint32_t a = t.declare("a");
  t.edge(a, Edge{-5_ns, Level::High});
  EXPECT_EQ(t.latest_sample_time(), -5_ns);
  t.edge(a, Edge{30_ns, Level::Low});
  t.edge(a, Edge{20_ns, Level::High}); // back in time: the latest stays
  EXPECT_EQ(t.latest_sample_time(), 30_ns);
}

TEST(TraceRecorder, KnowsWhetherSamplesCameInTimeOrder) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("a");
  const std::uint32_t n = t.declare("n", SignalKind::Integer, 8);
  EXPECT_TRUE(t.in_time_order());
  t.edge(a, Edge{10_ns, Level::High});
  t.value(n, 10_ns, 3); // equal times are in order
  t.edge(a, Edge{11_ns, Level::Low});
  EXPECT_TRUE(t.in_time_order());
  t.value(n, 10_ns, 4); // one nanosecond back
  EXPECT_FALSE(t.in_time_order());
  t.edge(a, Edge{20_ns, Level::High});
  EXPECT_FALSE(t.in_time_order()); // once out of order, the recording stays so
}

// A recorder that spills after a few samples writes the same VCD bytes, whole (with an overlay)
// or streamed, as one that holds everything: in time order and out of it.
TEST(TraceSpill, ATinySpillLimitGivesTheSameVcdBytes) {
  for (const std::uint64_t seed : {11U, 12U, 13U}) {
    for (const bool ordered : {true, false}) {
      TraceRecorder held;
      TraceRecorder spilled;
      spilled.spill_beyond(3);
      const std::vector<std::uint32_t> signals = declare_all(held);
      declare_all(spilled);
      // Streamed while the recording goes on (a stream writes late samples at a later time,
      // vcd_stream.hpp, so only the ordered recording streams to the same bytes).
      std::ostringstream streamed;
      VcdStream stream(streamed);
      // Non-negative times only: a VCD has no negative time.
      std::mt19937_64 rng(seed);
      std::int64_t now = 0;
      for (int i = 0; i < 1500; ++i) {
        now = ordered ? now + static_cast<std::int64_t>(rng() % 3000)
                      : static_cast<std::int64_t>(rng() % 1000000);
        const std::uint32_t s = signals[rng() % signals.size()];
        for (TraceRecorder* t : {&held, &spilled}) {
          if (t->signals()[s].kind == SignalKind::Wire) {
            t->edge(s, Edge{Nanos{now}, level_of(i % 3 == 0)});
          } else if (t->signals()[s].kind == SignalKind::Integer) {
            t->value(s, Nanos{now}, i % 5 == 0 ? kMin : -i);
          } else {
            t->real(s, Nanos{now}, i % 7 == 0 ? std::numeric_limits<double>::infinity() : i * 0.25);
          }
        }
        if (ordered && i % 97 == 0) stream.update(spilled);
      }
      ASSERT_GT(spilled.sample_count(), 3U * 100U);
      EXPECT_EQ(spilled.in_time_order(), ordered);
      EXPECT_EQ(held.in_time_order(), ordered);
      const std::vector<TraceSample> overlay{{Nanos{500}, signals[0], 1, 0.0},
                                             {Nanos{200}, signals[1], 0, 0.0}};
      const std::string expected = vcd_with_overlay(held, overlay);
      EXPECT_EQ(vcd_with_overlay(spilled, overlay), expected) << "seed " << seed;
      EXPECT_EQ(spilled.canonical_text(), held.canonical_text());
      EXPECT_EQ(spilled.edges_of("w.a"), held.edges_of("w.a"));
      if (!ordered) continue;
      stream.update(spilled);
      EXPECT_EQ(streamed.str(), vcd_with_overlay(held)) << "seed " << seed;
    }
  }
}

// A run's recorder holds its whole budget before it spills: 65,536 samples (2 MiB of 32-byte
// samples). One sample short of the limit nothing has left memory; the limit-th sample sends
// all of them to the file as one block, and each later 65,536 another; they read back as
// recorded, from the start and from inside the second and the last block.
TEST(TraceSpill, ARunHoldsItsWholeBudgetBeforeItSpills) {
  static_assert(sizeof(TraceSample) == 32);
  ASSERT_EQ(kTraceHeldSamples, std::size_t{65'536});
  const std::size_t limit = kTraceHeldSamples;
  TraceRecorder t;
  t.spill_beyond(limit);
  EXPECT_EQ(t.spill_limit(), limit);
  const std::uint32_t count = t.declare("enc.count", SignalKind::Integer, 32);
  const auto at = [](std::size_t i) { return static_cast<std::int64_t>(i); };
  for (std::size_t i = 0; i + 1 < limit; ++i) t.value(count, Nanos{at(i)}, at(i) % 1000);
  EXPECT_EQ(t.samples().size(), limit - 1); // held, none spilled
  EXPECT_EQ(t.sample_count(), limit - 1);
  t.value(count, Nanos{at(limit - 1)}, at(limit - 1) % 1000);
  EXPECT_TRUE(t.samples().empty()); // the limit-th: all of them in the file
  EXPECT_EQ(t.sample_count(), limit);
  // Three blocks in the file (3 * 65,536 = 196,608 samples) and one sample held.
  const std::size_t total = 3 * limit + 1;
  for (std::size_t i = limit; i < total; ++i) t.value(count, Nanos{at(i)}, at(i) % 1000);
  EXPECT_EQ(t.samples().size(), 1U);
  EXPECT_EQ(t.sample_count(), total);
  // From the start, from inside the second block (70,000) and from inside the last (its first
  // sample is 131,072).
  for (const std::size_t from : {std::size_t{0}, std::size_t{70'000}, total - 5}) {
    std::size_t next = from;
    bool same = true;
    t.visit_samples(from, [&](std::span<const TraceSample> chunk) {
      for (const TraceSample& s : chunk) {
        same = same && s.time == Nanos{at(next)} && s.signal == count && s.value == at(next) % 1000;
        ++next;
      }
    });
    EXPECT_EQ(next, total) << "from " << from;
    EXPECT_TRUE(same) << "from " << from;
  }
}
