#include "rig/campaign/run_trace.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <set>

#include <fmt/format.h>

namespace hilrig::campaign {

ShaftTrace::ShaftTrace(TraceRecorder& trace, double counts_per_turn, std::int64_t initial_count)
    : trace_(trace), per_turn_(std::max<std::int64_t>(1, std::llround(counts_per_turn))),
      count_signal_(trace.declare("shaft.count", SignalKind::Integer, 64)),
      position_signal_(trace.declare("shaft.position", SignalKind::Integer, 32)) {
  trace_.set_initial(count_signal_, initial_count);
  trace_.set_initial(position_signal_, position_of(initial_count));
}

std::int64_t ShaftTrace::position_of(std::int64_t count) const {
  const std::int64_t p = count % per_turn_;
  return p < 0 ? p + per_turn_ : p; // the count reverse of zero is the end of the turn
}

void ShaftTrace::count(Nanos t, std::int64_t count) {
  trace_.value(count_signal_, t, count);
  trace_.value(position_signal_, t, position_of(count));
}

namespace {

// Samples the stators at each excitation peak until `end`, one event a period. The events hold
// a plain pointer (a std::function keeps it without a heap block); the caller owns the sampler.
struct StatorSampler {
  Scheduler& sched;
  TraceRecorder& trace;
  Waveform sin, cos;
  std::uint32_t sin_signal, cos_signal;
  double first_ns, period_ns;
  Nanos end;
  std::int64_t k = 0;

  [[nodiscard]] Nanos peak(std::int64_t i) const {
    return Nanos{std::llround(first_ns + static_cast<double>(i) * period_ns)};
  }
  void next() {
    const Nanos at = peak(k);
    if (at > end) return;
    sched.at(at, [this] {
      const Nanos t = peak(k);
      trace.real(sin_signal, t, sin(t));
      trace.real(cos_signal, t, cos(t));
      ++k;
      next();
    });
  }
};

} // namespace

std::shared_ptr<void> trace_stators(Scheduler& scheduler, TraceRecorder& trace, const ResolverSpec& resolver,
                                    Waveform sin, Waveform cos, Nanos end) {
  if (!(resolver.excitation_hz > 0.0)) return nullptr;
  const double period_ns = 1e9 / resolver.excitation_hz;
  // sin(2 pi f t + phase) peaks where 2 pi f t + phase = pi/2 + 2 pi k.
  double cycles = 0.25 - resolver.phase_deg / 360.0;
  cycles -= std::floor(cycles);
  auto s = std::make_shared<StatorSampler>(StatorSampler{
      scheduler, trace, std::move(sin), std::move(cos), trace.declare(kStatorSin, SignalKind::Real),
      trace.declare(kStatorCos, SignalKind::Real), cycles * period_ns, period_ns, end});
  s->next();
  return s;
}

TracedHostWords::TracedHostWords(HostWords& words, const Scheduler& scheduler, TraceRecorder& trace,
                                 const duts::HostInterface& host, const std::vector<HostAction>& actions)
    : words_(words), sched_(scheduler), trace_(trace), host_(host) {
  if (host_.handshake && host_.output_words > 0 && host_.input_words > 0) {
    transmit_ = trace_.declare("host.transmit");
    acknowledge_ = trace_.declare("host.acknowledge");
  }
  // The words the actions name, declared in word order (the VCD lists them so) whatever order
  // the host uses them in; a word used otherwise is declared when first used.
  std::size_t written = 0;
  std::set<std::size_t> read;
  for (const HostAction& a : actions) {
    if (a.kind == HostAction::Kind::Write) written = std::max(written, a.words.size());
    if (a.kind == HostAction::Kind::Read) read.insert(a.word);
  }
  if (written > 0 && acknowledge_) read.insert(0);
  for (std::size_t k = 0; k < written; ++k) word_signal(out_, "out", k);
  for (const std::size_t k : read) word_signal(in_, "in", k);
}

TracedHostWords::Word& TracedHostWords::word_signal(std::vector<Word>& words, const char* direction,
                                                    std::size_t k) {
  if (words.size() <= k) words.resize(k + 1);
  Word& w = words[k];
  if (!w.declared) {
    w.signal = trace_.declare(fmt::format("host.{}{}", direction, k), SignalKind::Integer, 16);
    w.declared = true;
  }
  return w;
}

void TracedHostWords::note(Word& w, std::uint16_t value, std::optional<std::uint32_t> bit_signal,
                           unsigned bit) {
  if (w.seen && w.last == value) return; // a poll that read the same word again
  w.seen = true;
  w.last = value;
  trace_.value(w.signal, sched_.now(), value);
  if (bit_signal) trace_.value(*bit_signal, sched_.now(), (static_cast<unsigned>(value) >> bit) & 1U);
}

void TracedHostWords::write(std::size_t word, std::uint16_t value) {
  words_.write(word, value);
  note(word_signal(out_, "out", word), value, word == 0 ? transmit_ : std::nullopt, host_.transmit_bit);
}

std::uint16_t TracedHostWords::read(std::size_t word) {
  const std::uint16_t value = words_.read(word);
  note(word_signal(in_, "in", word), value, word == 0 ? acknowledge_ : std::nullopt, host_.acknowledge_bit);
  return value;
}

} // namespace hilrig::campaign
