// Each direction is a queue of bytes on its own wire: a byte starts when the one before it
// ends, and reaches the far end (and the trace) when its stop bit ends. A dropped byte still
// takes its time on the wire; a corrupted byte arrives (and is traced) as its new value.
#include "drivers/virtual/serial_link.hpp"

#include <deque>
#include <utility>
#include <vector>

namespace hilrig::virt {

struct SerialLink::Impl {
  struct Wire;

  struct End final : ByteLink {
    End(Impl& link, Wire& out) : link_(link), out_(out) {}
    void write(std::span<const std::uint8_t> bytes) override { link_.send(out_, bytes); }
    void on_byte(ByteHandler handler) override { handlers.push_back(std::move(handler)); }
    Impl& link_;
    Wire& out_;
    std::vector<ByteHandler> handlers;
  };

  struct Wire {
    SerialDirection direction;
    End* receiver = nullptr;
    std::deque<std::uint8_t> queue;
    bool busy = false;
  };

  Impl(Scheduler& s, std::string n, SerialFormat f, TraceRecorder* tr)
      : scheduler(s), name(std::move(n)), format(f), trace(tr) {
    a_to_b.receiver = &b;
    b_to_a.receiver = &a;
  }

  void send(Wire& wire, std::span<const std::uint8_t> bytes) {
    wire.queue.insert(wire.queue.end(), bytes.begin(), bytes.end());
    if (!wire.busy && !wire.queue.empty()) {
      wire.busy = true;
      scheduler.after(format.char_time(), [this, &wire] { stop_bit_end(wire); });
    }
  }

  void stop_bit_end(Wire& wire) {
    std::uint8_t byte = wire.queue.front();
    wire.queue.pop_front();
    // The next byte starts now, before handlers run (they may write more).
    if (wire.queue.empty()) {
      wire.busy = false;
    } else {
      scheduler.after(format.char_time(), [this, &wire] { stop_bit_end(wire); });
    }
    if (drop && drop(wire.direction, byte)) return;
    if (corrupt) byte = corrupt(wire.direction, byte);
    const Nanos t = scheduler.now();
    if (trace != nullptr) trace->serial(name, wire.direction, t, byte);
    for (const auto& handler : wire.receiver->handlers) handler(byte, t);
  }

  Scheduler& scheduler;
  std::string name;
  SerialFormat format;
  TraceRecorder* trace;
  Wire a_to_b{SerialDirection::AtoB, nullptr, {}, false};
  Wire b_to_a{SerialDirection::BtoA, nullptr, {}, false};
  End a{*this, a_to_b};
  End b{*this, b_to_a};
  Corrupt corrupt;
  Drop drop;
};

SerialLink::SerialLink(Scheduler& scheduler, std::string name, SerialFormat format, TraceRecorder* trace)
    : impl_(std::make_unique<Impl>(scheduler, std::move(name), format, trace)) {}

SerialLink::~SerialLink() = default;

ByteLink& SerialLink::end_a() { return impl_->a; }
ByteLink& SerialLink::end_b() { return impl_->b; }
const SerialFormat& SerialLink::format() const { return impl_->format; }
void SerialLink::set_corrupt(Corrupt corrupt) { impl_->corrupt = std::move(corrupt); }
void SerialLink::set_drop(Drop drop) { impl_->drop = std::move(drop); }

} // namespace hilrig::virt
