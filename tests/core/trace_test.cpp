#include "core/trace.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "core/vcd_stream.hpp"

using namespace hilrig;
using namespace hilrig::literals;

namespace {

// Reference FNV-1a 64, checked below against the published test vectors.
std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : s) {
    h ^= static_cast<std::uint8_t>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

// A seeded random trace: a few wires, an integer, a real, CAN frames and serial bytes.
// With `spill` > 0 the recorder keeps at most that many samples in memory (spill_beyond).
TraceRecorder random_trace(std::uint32_t seed, std::size_t spill = 0) {
  std::mt19937 rng(seed);
  TraceRecorder t;
  t.spill_beyond(spill);
  const std::uint32_t a = t.declare("rig.enc.A");
  const std::uint32_t b = t.declare("rig.enc.B");
  const std::uint32_t n = t.declare("dut.count", SignalKind::Integer, 16);
  const std::uint32_t v = t.declare("dut.volt", SignalKind::Real);
  t.set_initial(a, 0);
  t.set_initial(b, 1);
  std::int64_t now = 0;
  int level_a = 0;
  for (int i = 0; i < 200; ++i) {
    now += static_cast<std::int64_t>(rng() % 5000);
    switch (rng() % 5) {
    case 0:
      level_a ^= 1;
      t.edge(a, Edge{Nanos{now}, level_of(level_a != 0)});
      break;
    case 1:
      t.value(n, Nanos{now}, static_cast<std::int64_t>(rng() % 65536));
      break;
    case 2:
      t.real(v, Nanos{now}, static_cast<double>(rng() % 1000) / 64.0);
      break;
    case 3: {
      CanFrame f;
      f.id = rng() % 0x800;
      f.len = static_cast<std::uint8_t>(rng() % 9);
      for (std::size_t k = 0; k < f.len; ++k) f.data[k] = static_cast<std::uint8_t>(rng());
      t.can("can0", Nanos{now}, f);
      break;
    }
    default:
      t.serial("host", SerialDirection::AtoB, Nanos{now}, static_cast<std::uint8_t>(rng()));
      break;
    }
  }
  return t;
}

std::string vcd_of(const TraceRecorder& t) {
  std::ostringstream out;
  write_vcd(t, out);
  return out.str();
}

} // namespace

TEST(TraceRecorder, DeclareIsIdempotentAndFindKnowsNames) {
  TraceRecorder t;
  EXPECT_EQ(t.declare("rig.a"), 0U);
  EXPECT_EQ(t.declare("rig.b", SignalKind::Integer, 12), 1U);
  EXPECT_EQ(t.declare("rig.a"), 0U);
  EXPECT_EQ(t.find("rig.b"), 1);
  EXPECT_EQ(t.find("nope"), -1);
  EXPECT_EQ(t.signals().size(), 2U);
  EXPECT_THROW(t.declare("rig.a", SignalKind::Real), std::invalid_argument);
  EXPECT_THROW(t.declare("rig.c", SignalKind::Integer, 65), std::invalid_argument);
}

TEST(TraceRecorder, KindMismatchIsRejected) {
  TraceRecorder t;
  const std::uint32_t r = t.declare("v", SignalKind::Real);
  EXPECT_THROW(t.edge(r, Edge{1_us, Level::High}), std::invalid_argument);
  EXPECT_THROW(t.value(r, 1_us, 3), std::invalid_argument);
  EXPECT_THROW(t.edge(7, Edge{1_us, Level::High}), std::out_of_range);
}

TEST(TraceRecorder, EdgesOfReturnsOneWireInTimeOrder) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("a");
  const std::uint32_t b = t.declare("b");
  t.edge(a, Edge{1_us, Level::High});
  t.edge(b, Edge{2_us, Level::High});
  t.edge(a, Edge{3_us, Level::Low});
  EXPECT_EQ(t.edges_of("a"), (std::vector<Edge>{{1_us, Level::High}, {3_us, Level::Low}}));
  EXPECT_EQ(t.edges_of("b"), (std::vector<Edge>{{2_us, Level::High}}));
  EXPECT_TRUE(t.edges_of("c").empty());
}

// keep_edges_of: the edges of the kept Wire signals, recorded by edge() or value(), declared
// before the call or after it, spilled or held, are what reading the samples back gives; a name
// not kept, not a wire or not declared, asked with kept ones, is read back as before; a call
// after the first sample keeps nothing.
TEST(TraceRecorder, EdgesKeptAsRecordedAreTheEdgesReadBack) {
  for (const std::uint32_t seed : {1U, 2U, 3U, 4U}) {
    for (const std::size_t spill : {std::size_t{0}, std::size_t{5}, std::size_t{64}}) {
      for (const bool late : {false, true}) {
        SCOPED_TRACE("seed " + std::to_string(seed) + " spill " + std::to_string(spill) +
                     (late ? " keep after a sample" : ""));
        std::mt19937 rng(seed);
        TraceRecorder kept;
        TraceRecorder plain;
        const std::vector<std::string> names{"early", "late", "count", "nowhere"};
        for (TraceRecorder* t : {&kept, &plain}) {
          t->spill_beyond(spill);
          (void)t->declare("early");
          (void)t->declare("count", SignalKind::Integer, 16);
        }
        if (late) {
          kept.value(0, Nanos{0}, 1);
          plain.value(0, Nanos{0}, 1);
        }
        kept.keep_edges_of(names);
        for (TraceRecorder* t : {&kept, &plain}) {
          (void)t->declare("late");
          (void)t->declare("other");
        }
        std::int64_t now = 0;
        for (int i = 0; i < 400; ++i) {
          now += static_cast<std::int64_t>(rng() % 3); // equal times too
          const std::uint32_t signal = rng() % 4;
          const auto v = static_cast<std::int64_t>(signal == 1 ? rng() % 1000 : rng() % 2);
          const bool by_edge = signal != 1 && rng() % 2 == 0;
          for (TraceRecorder* t : {&kept, &plain}) {
            if (by_edge)
              t->edge(signal, Edge{Nanos{now}, level_of(v != 0)});
            else
              t->value(signal, Nanos{now}, v);
          }
        }
        EXPECT_EQ(kept.edges_of(names), plain.edges_of(names));
        const std::vector<std::string> wires{"late", "early"};
        EXPECT_EQ(kept.edges_of(wires), plain.edges_of(wires));
        EXPECT_FALSE(kept.edges_of("late").empty());
        EXPECT_EQ(kept.edges_of("late"), plain.edges_of("late"));
        EXPECT_EQ(kept.edges_of("other"), plain.edges_of("other")); // not kept: read back
        EXPECT_EQ(kept.canonical_text(), plain.canonical_text());
      }
    }
  }
}

TEST(TraceRecorder, Fnv1aReferenceMatchesPublishedVectors) {
  // FNV-1a 64 test vectors (Fowler/Noll/Vo reference): "" and "a".
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cULL);
}

TEST(TraceRecorder, CanonicalTextIsTheDocumentedFormatAndHashIsItsFnv1a) {
  TraceRecorder t;
  const std::uint32_t a = t.declare("rig.A");
  const std::uint32_t r = t.declare("rig.V", SignalKind::Real);
  t.set_initial(a, 0);
  t.edge(a, Edge{1500_ns, Level::High});
  t.real(r, 2_us, 1.0); // IEEE-754 1.0 = 0x3ff0000000000000
  CanFrame f;
  f.id = 0x123;
  f.len = 2;
  f.data[0] = 0xAB;
  f.data[1] = 0x01;
  t.can("can0", 3_us, f);
  t.serial("host", SerialDirection::BtoA, 4_us, 0x5A);
  const std::string expected = "hilrig-trace 1\n"
                               "signal 0 rig.A wire 1 0\n"
                               "signal 1 rig.V real 64 x\n"
                               "sample 1500 0 1\n"
                               "sample 2000 1 r3ff0000000000000\n"
                               "can 3000 can0 123#AB01\n"
                               "serial 4000 host ba 5a\n";
  EXPECT_EQ(t.canonical_text(), expected);
  EXPECT_EQ(t.content_hash(), fnv1a(expected));
}

TEST(TraceRecorder, IdenticalInputsGiveIdenticalVcdAndHash) {
  // Property over seeds: the same recorded input twice is byte-identical in VCD and hash.
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    const TraceRecorder x = random_trace(seed);
    const TraceRecorder y = random_trace(seed);
    EXPECT_EQ(vcd_of(x), vcd_of(y)) << "seed " << seed;
    EXPECT_EQ(x.content_hash(), y.content_hash()) << "seed " << seed;
  }
}

TEST(TraceRecorder, DifferentInputGivesDifferentHash) {
  const TraceRecorder base = random_trace(7);
  EXPECT_NE(base.content_hash(), random_trace(8).content_hash());
  // A single edge one nanosecond later changes the hash.
  TraceRecorder x;
  TraceRecorder y;
  for (TraceRecorder* t : {&x, &y}) t->declare("a");
  x.edge(0, Edge{100_ns, Level::High});
  y.edge(0, Edge{101_ns, Level::High});
  EXPECT_NE(x.content_hash(), y.content_hash());
  // So does one serial byte's direction.
  TraceRecorder p;
  TraceRecorder q;
  p.serial("l", SerialDirection::AtoB, 1_us, 1);
  q.serial("l", SerialDirection::BtoA, 1_us, 1);
  EXPECT_NE(p.content_hash(), q.content_hash());
}

// TMPDIR set to `dir` while it lives, then as it was.
class TmpdirAs {
public:
  explicit TmpdirAs(const std::string& dir) {
    if (const char* old = std::getenv("TMPDIR")) old_ = old;
    setenv("TMPDIR", dir.c_str(), 1);
  }
  ~TmpdirAs() {
    if (old_) {
      setenv("TMPDIR", old_->c_str(), 1);
    } else {
      unsetenv("TMPDIR");
    }
  }
  TmpdirAs(const TmpdirAs&) = delete;
  TmpdirAs& operator=(const TmpdirAs&) = delete;

private:
  std::optional<std::string> old_;
};

// The spill file goes where TMPDIR says (std::tmpfile would take /tmp whatever it says: the RT
// VM lane's guest has a read-only /tmp and a long campaign there stopped with a rig fault),
// and leaves no name behind.
TEST(TraceSpill, GoesToTmpdirAndLeavesNoFile) {
  const std::filesystem::path dir =
      std::filesystem::path(HILRIG_BINARY_DIR) / "tests" / "core" / "spill_tmpdir";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    const TmpdirAs tmpdir(dir.string());
    const TraceRecorder spilled = random_trace(1, 7);
    EXPECT_EQ(spilled.canonical_text(), random_trace(1).canonical_text());
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  // A TMPDIR that is not a directory: a clear error, not a file elsewhere.
  const TmpdirAs missing((dir / "missing").string());
  try {
    (void)random_trace(1, 7);
    ADD_FAILURE() << "spilled without a temporary directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("TMPDIR"), std::string::npos) << e.what();
  }
}

// A long run's trace moves to a temporary file as it grows: everything read from it (the
// canonical text, a line's edges, the VCD, written whole or streamed) is what it was in memory.
TEST(TraceSpill, ReadsAsIfEverySampleWereHeld) {
  for (const std::uint32_t seed : {1U, 2U, 3U}) {
    const TraceRecorder held = random_trace(seed);
    const TraceRecorder spilled = random_trace(seed, 7);
    EXPECT_LE(spilled.samples().size(), 7U);
    EXPECT_EQ(spilled.sample_count(), held.sample_count());
    EXPECT_EQ(spilled.canonical_text(), held.canonical_text());
    EXPECT_EQ(spilled.content_hash(), held.content_hash());
    EXPECT_EQ(spilled.edges_of("rig.enc.A"), held.edges_of("rig.enc.A"));
    EXPECT_EQ(vcd_of(spilled), vcd_of(held));
    std::ostringstream streamed;
    VcdStream stream(streamed);
    stream.update(spilled);
    EXPECT_EQ(streamed.str(), vcd_of(held));
  }
}

TEST(TraceSpill, HandFedSamplesOutOfTimeOrderAreStillSortedInTheVcd) {
  TraceRecorder t;
  t.spill_beyond(2);
  const std::uint32_t a = t.declare("a");
  const std::uint32_t b = t.declare("b");
  t.edge(a, Edge{30_ns, Level::High});
  t.edge(b, Edge{10_ns, Level::High});
  t.edge(a, Edge{20_ns, Level::Low});
  t.edge(b, Edge{10_ns, Level::Low});
  t.edge(a, Edge{5_ns, Level::High});
  EXPECT_EQ(t.edges_of("a"),
            (std::vector<Edge>{{5_ns, Level::High}, {20_ns, Level::Low}, {30_ns, Level::High}}));
  const std::string vcd = vcd_of(t);
  // Times ascending; the two samples at 10 ns in the order they were recorded.
  EXPECT_TRUE(vcd.ends_with("$end\n#5\n1!\n#10\n1\"\n0\"\n#20\n0!\n#30\n1!\n")) << vcd;
}
