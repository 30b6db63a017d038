#include "drivers/virtual/digital_line.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hilrig::virt {

struct DigitalLine::Impl {
  struct Reader final : LineInput {
    explicit Reader(const Impl& line) : line_(line) {}
    [[nodiscard]] Level level() const override { return line_.seen; }
    void on_edge(EdgeHandler handler) override { handlers.push_back(std::move(handler)); }
    const Impl& line_;
    std::vector<EdgeHandler> handlers;
  };

  struct Driver final : LineOutput {
    explicit Driver(Impl& line) : line_(line) {}
    void set(Level level) override { line_.drive(level); }
    [[nodiscard]] Level driven() const override { return line_.driven; }
    Impl& line_;
  };

  Impl(Scheduler& s, Level initial, TraceRecorder* tr, std::uint32_t sig)
      : scheduler(s), trace(tr), signal(sig), driven(initial), seen(initial) {}

  void drive(Level level) {
    if (level == driven) return; // the same level again is not an edge
    driven = level;
    if (powering_up) {
      start_at(level);
      return;
    }
    if (delay == Nanos::zero() && last_delivery <= scheduler.now()) {
      deliver(level);
      return;
    }
    // Never before an edge already on its way, so readers see edges in the order driven
    // even when the delay was shortened meanwhile.
    last_delivery = std::max(scheduler.now() + delay, last_delivery);
    scheduler.at(last_delivery, [this, level] { deliver(level); });
  }

  // The level the line starts at, as if it had been made with it.
  void start_at(Level level) {
    seen = level;
    if (trace != nullptr) trace->set_initial(signal, is_high(level) ? 1 : 0);
  }

  void deliver(Level level) {
    if (level == seen) return;
    seen = level;
    ++edges;
    const Edge e{scheduler.now(), level};
    if (trace != nullptr) trace->edge(signal, e);
    for (const auto& reader : readers) {
      for (const auto& handler : reader->handlers) handler(e);
    }
  }

  Scheduler& scheduler;
  TraceRecorder* trace;
  std::uint32_t signal;
  Level driven;
  Level seen;
  Nanos delay{0};
  bool powering_up = false;
  Nanos last_delivery = Nanos::min();
  std::uint64_t edges = 0;
  Driver driver{*this};
  std::vector<std::unique_ptr<Reader>> readers;
};

DigitalLine::DigitalLine(Scheduler& scheduler, std::string name, Level initial, TraceRecorder* trace)
    : name_(std::move(name)) {
  std::uint32_t signal = 0;
  if (trace != nullptr) {
    signal = trace->declare(name_, SignalKind::Wire);
    trace->set_initial(signal, is_high(initial) ? 1 : 0);
  }
  impl_ = std::make_unique<Impl>(scheduler, initial, trace, signal);
}

DigitalLine::~DigitalLine() = default;

void DigitalLine::set_propagation_delay(Nanos delay) {
  if (delay < Nanos::zero()) throw std::invalid_argument("DigitalLine: negative propagation delay");
  impl_->delay = delay;
}

Nanos DigitalLine::propagation_delay() const { return impl_->delay; }

void DigitalLine::set_powering_up(bool on) { impl_->powering_up = on; }

LineOutput& DigitalLine::driver() { return impl_->driver; }

LineInput& DigitalLine::reader() {
  impl_->readers.push_back(std::make_unique<Impl::Reader>(*impl_));
  return *impl_->readers.back();
}

Level DigitalLine::level() const { return impl_->seen; }
std::uint64_t DigitalLine::edge_count() const { return impl_->edges; }

} // namespace hilrig::virt
