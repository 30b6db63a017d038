// VCD (IEEE 1364-2005 §18) writer. Layout:
//   $date <comment> $end        (only when a date comment is given, so runs compare equal)
//   $version hilrig $end
//   $timescale 1ns $end
//   $scope module a $end ... $var <type> <width> <id> <last name part> $end ... $upscope $end
//   $enddefinitions $end
//   #0 $dumpvars <initial values> $end
//   <value changes, each time block opened by #t, times strictly ascending>
// Wires are 1-bit "wire" vars (0/1/x), Integers "integer" vars of their width written as
// b<binary> (two's complement within the width), Reals "real" vars written as r<shortest
// round-trip decimal>. Identifier codes are base-94 over the printable ASCII '!'..'~'.
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "core/trace.hpp"
#include "core/vcd_stream.hpp"

namespace hilrig {
namespace {

std::string id_code(std::size_t index) {
  std::string id;
  do {
    id.push_back(static_cast<char>('!' + index % 94));
    index /= 94;
  } while (index > 0);
  return id;
}

std::string sanitized(std::string_view part) {
  std::string s(part);
  for (char& c : s) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
  }
  return s.empty() ? std::string("_") : s;
}

std::vector<std::string_view> split_dots(std::string_view name) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = name.find('.', start);
    parts.push_back(name.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

// A scope holds its variables and sub-scopes in the order they were first declared.
struct Scope {
  std::string name;
  std::vector<std::pair<bool, std::size_t>> items; // (is_scope, index into scopes/vars)
  std::vector<Scope> scopes;
};

void add_var(Scope& root, std::string_view full_name, std::size_t signal) {
  const std::vector<std::string_view> parts = split_dots(full_name);
  Scope* scope = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string part = sanitized(parts[i]);
    auto it = std::find_if(scope->scopes.begin(), scope->scopes.end(),
                           [&](const Scope& s) { return s.name == part; });
    if (it == scope->scopes.end()) {
      scope->items.emplace_back(true, scope->scopes.size());
      scope->scopes.push_back(Scope{part, {}, {}});
      it = scope->scopes.end() - 1;
    }
    scope = &*it;
  }
  scope->items.emplace_back(false, signal);
}

void write_scope(std::ostream& out, const Scope& scope, const std::vector<SignalInfo>& signals) {
  for (const auto& [is_scope, index] : scope.items) {
    if (is_scope) {
      const Scope& sub = scope.scopes[index];
      out << "$scope module " << sub.name << " $end\n";
      write_scope(out, sub, signals);
      out << "$upscope $end\n";
      continue;
    }
    const SignalInfo& s = signals[index];
    const std::string leaf = sanitized(split_dots(s.name).back());
    switch (s.kind) {
    case SignalKind::Wire:
      out << "$var wire 1 ";
      break;
    case SignalKind::Integer:
      out << "$var integer " << static_cast<unsigned>(s.width) << ' ';
      break;
    case SignalKind::Real:
      out << "$var real 64 ";
      break;
    }
    out << id_code(index) << ' ' << leaf << " $end\n";
  }
}

// The eight binary digits of each byte value, most significant first: an integer's digits are
// copied a byte at a time (a shaft count has ~20 of them, at every encoder edge).
constexpr std::array<std::array<char, 8>, 256> kByteDigits = [] {
  std::array<std::array<char, 8>, 256> table{};
  for (std::size_t v = 0; v < 256; ++v)
    for (std::size_t i = 0; i < 8; ++i) table[v][i] = static_cast<char>('0' + ((v >> (7 - i)) & 1U));
  return table;
}();

// The most characters format_value writes besides the identifier: 'b' and 64 digits and a
// space, or 'r', a double's shortest text (at most 24) and a space; and the newline.
constexpr std::size_t kValueChars = 1 + 64 + 1 + 1;

// kByteDigits with each row padded to 16 characters: the last r digits of a byte are copied
// as one 8-character word from its row + 8 - r (the padding after them is overwritten by the
// characters that follow).
constexpr std::array<std::array<char, 16>, 256> kPaddedByteDigits = [] {
  std::array<std::array<char, 16>, 256> table{};
  for (std::size_t v = 0; v < 256; ++v)
    for (std::size_t i = 0; i < 8; ++i) table[v][i] = kByteDigits[v][i];
  return table;
}();

// Writes bits' binary digits from the most significant one (one "0" for zero) at `at` and
// returns their end. The digits above the last whole byte come as one 8-character word from
// their row, so up to 7 characters past the end may be written (room the callers leave: the
// line's rest overwrites them).
char* put_binary(char* at, std::uint64_t bits) {
  int left = bits == 0 ? 1 : 64 - std::countl_zero(bits);
  if (const int part = left % 8; part != 0) {
    left -= part;
    std::memcpy(at, kPaddedByteDigits[bits >> static_cast<unsigned>(left)].data() + (8 - part), 8);
    at += part;
  }
  for (; left > 0; left -= 8) {
    std::memcpy(at, kPaddedByteDigits[(bits >> static_cast<unsigned>(left - 8)) & 0xFFU].data(), 8);
    at += 8;
  }
  return at;
}

// Formats one value change ("1!", "b110 #", "r1.25 $") and its newline at `line`, which has
// room for kValueChars and the identifier; returns the characters written.
std::size_t format_value(char* line, const SignalInfo& s, std::string_view id, std::int64_t v, double r) {
  std::size_t n = 0;
  switch (s.kind) {
  case SignalKind::Wire:
    line[n++] = v != 0 ? '1' : '0';
    break;
  case SignalKind::Integer: {
    auto bits = static_cast<std::uint64_t>(v);
    if (s.width < 64) bits &= (std::uint64_t{1} << s.width) - 1U;
    line[n++] = 'b';
    n = static_cast<std::size_t>(put_binary(line + n, bits) - line);
    line[n++] = ' ';
    break;
  }
  case SignalKind::Real: {
    line[n++] = 'r';
    const auto res = std::to_chars(line + n, line + 64, r);
    n = static_cast<std::size_t>(res.ptr - line);
    line[n++] = ' ';
    break;
  }
  }
  id.copy(line + n, id.size());
  n += id.size();
  line[n++] = '\n';
  return n;
}

// Appends one value change and its newline to `out`.
void append_value(std::string& out, const SignalInfo& s, std::string_view id, std::int64_t v, double r) {
  const std::size_t at = out.size();
  out.resize(at + kValueChars + id.size());
  out.resize(at + format_value(out.data() + at, s, id, v, r));
}

void write_value(std::ostream& out, const SignalInfo& s, std::size_t index, std::int64_t v, double r) {
  std::string text;
  append_value(text, s, id_code(index), v, r);
  out << text;
}

void write_header(std::ostream& out, const std::vector<SignalInfo>& signals, std::string_view date) {
  if (!date.empty()) out << "$date\n  " << date << "\n$end\n";
  out << "$version\n  hilrig trace\n$end\n$timescale 1ns $end\n";
  Scope root;
  for (std::size_t i = 0; i < signals.size(); ++i) add_var(root, signals[i].name, i);
  write_scope(out, root, signals);
  out << "$enddefinitions $end\n#0\n$dumpvars\n";
  for (std::size_t i = 0; i < signals.size(); ++i) {
    const SignalInfo& s = signals[i];
    if (s.has_initial) {
      write_value(out, s, i, s.initial, s.initial_real);
    } else if (s.kind == SignalKind::Wire) {
      out << 'x' << id_code(i) << '\n';
    } else if (s.kind == SignalKind::Integer) {
      out << "bx " << id_code(i) << '\n';
    } else {
      out << "r0 " << id_code(i) << '\n'; // a real has no unknown value in VCD
    }
  }
  out << "$end\n";
}

void check_time(Nanos t) {
  if (t < Nanos::zero()) throw std::invalid_argument("VCD: negative sample time");
}

// "00" .. "99": a number's decimal digits two at a time.
constexpr std::array<char, 200> kDigitPairs = [] {
  std::array<char, 200> table{};
  for (std::size_t v = 0; v < 100; ++v) {
    table[2 * v] = static_cast<char>('0' + v / 10);
    table[2 * v + 1] = static_cast<char>('0' + v % 10);
  }
  return table;
}();

// 10^0 .. 10^19.
constexpr std::array<std::uint64_t, 20> kPowersOf10 = [] {
  std::array<std::uint64_t, 20> table{};
  std::uint64_t p = 1;
  for (std::uint64_t& t : table) {
    t = p;
    p *= 10;
  }
  return table;
}();

// Writes v's decimal digits at `at`; returns the end. The same text as std::to_chars.
char* put_decimal(char* at, std::uint64_t v) {
  if (v < 10) {
    *at = static_cast<char>('0' + v);
    return at + 1;
  }
  // floor(log10(2^bits)) from the bit length (1233 / 4096 ~ log10 2), then one compare.
  const auto bits = static_cast<std::size_t>(64 - std::countl_zero(v));
  const std::size_t guess = (bits * 1233) >> 12U;
  char* const end = at + guess + (v >= kPowersOf10[guess] ? 1 : 0);
  char* p = end;
  for (; v >= 100; v /= 100) {
    p -= 2;
    std::memcpy(p, kDigitPairs.data() + 2 * (v % 100), 2);
  }
  if (v >= 10) {
    std::memcpy(p - 2, kDigitPairs.data() + 2 * v, 2);
  } else {
    p[-1] = static_cast<char>('0' + v);
  }
  return end;
}

// The value changes after $dumpvars: "#t" before the first change at each new time, then the
// changes. Formats into a buffer written out in large blocks: a long run has millions of
// changes, and ostream formatting per change was most of the writing time. Writes a change
// with fixed-size copies that may run up to kOverrun characters past its end (overwritten by
// the next; the buffer has room for them).
class VcdBody {
public:
  VcdBody(std::ostream& out, const std::vector<SignalInfo>& signals, std::size_t declared)
      : out_(out), signals_(signals) {
    ids_.reserve(declared);
    written_.reserve(declared);
    std::size_t longest = 0;
    for (std::size_t i = 0; i < declared; ++i) {
      ids_.push_back(id_code(i));
      longest = std::max(longest, ids_.back().size());
      const SignalInfo& s = signals[i];
      Written w;
      w.kind = s.kind;
      w.mask = s.width < 64 ? (std::uint64_t{1} << s.width) - 1U : ~std::uint64_t{0};
      w.short_id = ids_.back().size() <= w.id.size();
      if (w.short_id) {
        ids_.back().copy(w.id.data(), ids_.back().size());
        w.id_size = static_cast<std::uint8_t>(ids_.back().size());
      }
      written_.push_back(w);
    }
    // Room for a "#t" line and a change after the block's last byte, and the overrun.
    buffer_ = std::make_unique_for_overwrite<char[]>(kBlock + kTimeChars + kValueChars + longest + kOverrun);
  }
  ~VcdBody() = default;
  VcdBody(const VcdBody&) = delete;
  VcdBody& operator=(const VcdBody&) = delete;

  // Writes one sample, opening a new "#t" block when its time is later than `time`; returns
  // false when it is earlier (it is then written at the later time, as VcdStream documents).
  bool add(const TraceSample& s, std::int64_t& time) {
    check_time(s.time);
    bool in_order = true;
    char* at = buffer_.get() + used_;
    if (s.time.count() < time) {
      in_order = false;
    } else if (s.time.count() != time) {
      time = s.time.count();
      *at++ = '#';
      at = put_decimal(at, static_cast<std::uint64_t>(time));
      *at++ = '\n';
    }
    const Written& w = written_[s.signal];
    if (w.kind == SignalKind::Real || !w.short_id) {
      at += format_value(at, signals_[s.signal], ids_[s.signal], s.value, s.real);
    } else {
      if (w.kind == SignalKind::Wire) {
        *at++ = s.value != 0 ? '1' : '0';
      } else {
        *at++ = 'b';
        at = put_binary(at, static_cast<std::uint64_t>(s.value) & w.mask);
        *at++ = ' ';
      }
      std::memcpy(at, w.id.data(), w.id.size());
      at += w.id_size;
      *at++ = '\n';
    }
    used_ = static_cast<std::size_t>(at - buffer_.get());
    if (used_ >= kBlock) flush();
    return in_order;
  }

  void flush() {
    out_.write(buffer_.get(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

private:
  // A signal as add() writes it: identifiers of up to 8 characters (94^8 signals) copied as one
  // word; reals and longer identifiers through format_value.
  struct Written {
    SignalKind kind = SignalKind::Wire;
    bool short_id = false;
    std::uint8_t id_size = 0;
    std::uint64_t mask = 0;
    std::array<char, 8> id{};
  };
  // A block of 1 MiB: at least the buffer of write_file_atomically's stream, which then writes
  // it straight out instead of copying it into that buffer first.
  static constexpr std::size_t kBlock = std::size_t{1} << 20U;
  static constexpr std::size_t kTimeChars = 1 + 20 + 1; // '#', an int64, '\n'
  static constexpr std::size_t kOverrun = 8;
  std::ostream& out_;
  const std::vector<SignalInfo>& signals_;
  std::vector<std::string> ids_;
  std::vector<Written> written_;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

} // namespace

void write_vcd(const TraceRecorder& trace, std::ostream& out, std::string_view date_comment,
               std::span<const TraceSample> overlay) {
  const std::vector<SignalInfo>& signals = trace.signals();
  for (const TraceSample& s : overlay)
    if (s.signal >= signals.size())
      throw std::invalid_argument("VCD: overlay sample of an undeclared signal");
  std::vector<TraceSample> extra(overlay.begin(), overlay.end());
  std::stable_sort(extra.begin(), extra.end(),
                   [](const TraceSample& a, const TraceSample& b) { return a.time < b.time; });
  write_header(out, signals, date_comment);
  // A scheduler records in time order: then the samples are written as they come, in one pass
  // (a spilled trace is never held whole). Otherwise they are sorted by time, stably.
  const bool sorted = trace.in_time_order();
  VcdBody body(out, signals, signals.size());
  std::int64_t time = 0;
  std::size_t next_extra = 0;
  // The overlay's samples earlier than `t` (all of them at the end), before the sample at t.
  const auto add_extra_before = [&](Nanos t) {
    for (; next_extra < extra.size() && extra[next_extra].time < t; ++next_extra)
      body.add(extra[next_extra], time);
  };
  if (sorted) {
    trace.visit_samples(0, [&](std::span<const TraceSample> chunk) {
      for (const TraceSample& s : chunk) {
        add_extra_before(s.time);
        body.add(s, time);
      }
    });
  } else {
    std::vector<TraceSample> samples;
    samples.reserve(trace.sample_count());
    trace.visit_samples(0, [&](std::span<const TraceSample> chunk) {
      samples.insert(samples.end(), chunk.begin(), chunk.end());
    });
    std::stable_sort(samples.begin(), samples.end(),
                     [](const TraceSample& a, const TraceSample& b) { return a.time < b.time; });
    for (const TraceSample& s : samples) {
      add_extra_before(s.time);
      body.add(s, time);
    }
  }
  add_extra_before(Nanos::max());
  for (; next_extra < extra.size(); ++next_extra) body.add(extra[next_extra], time);
  body.flush();
}

VcdStream::VcdStream(std::ostream& out, std::string_view date_comment) : out_(out), date_(date_comment) {}

void VcdStream::update(const TraceRecorder& trace) {
  const std::vector<SignalInfo>& signals = trace.signals();
  if (!started_) {
    write_header(out_, signals, date_);
    declared_ = signals.size();
    started_ = true;
  }
  VcdBody body(out_, signals, declared_);
  trace.visit_samples(next_, [&](std::span<const TraceSample> chunk) {
    for (const TraceSample& s : chunk) {
      if (s.signal >= declared_) {
        ++skipped_;
        continue;
      }
      if (!body.add(s, time_)) ++late_;
    }
  });
  next_ = trace.sample_count();
  body.flush();
  out_.flush();
}

} // namespace hilrig
