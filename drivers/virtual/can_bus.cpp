// The virtual CAN bus: one frame on the wire at a time, arbitration at each idle instant.
// Timing and fault rules are described in can_bus.hpp.
#include "drivers/virtual/can_bus.hpp"

#include <deque>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hilrig::virt {

class CanNode final : public CanPort {
public:
  CanNode(CanBus::Impl& bus, std::string name) : bus_(bus), name_(std::move(name)) {}
  void send(const CanFrame& frame) override;
  void on_receive(CanReceiveHandler handler) override { handlers_.push_back(std::move(handler)); }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] std::uint32_t tec() const { return tec_; }
  [[nodiscard]] bool is_bus_off() const { return bus_off_; }

private:
  friend struct CanBus::Impl;
  CanBus::Impl& bus_;
  std::string name_;
  std::deque<CanFrame> queue_;
  std::vector<CanReceiveHandler> handlers_;
  std::uint32_t tec_ = 0;
  bool bus_off_ = false;
};

struct CanBus::Impl {
  Impl(Scheduler& s, std::string n, CanBitTiming t, TraceRecorder* tr)
      : scheduler(s), name(std::move(n)), timing(t), trace(tr) {}

  Scheduler& scheduler;
  std::string name;
  CanBitTiming timing;
  TraceRecorder* trace;
  std::vector<std::unique_ptr<CanNode>> nodes;
  FrameFilter drop;
  FrameFilter error;
  bool busy = false; // a frame (or error frame) is on the wire, or arbitration is due now
  CanNode* sender = nullptr;
  CanFrame current{};
  std::uint64_t delivered = 0;
  std::uint64_t errors = 0;
  std::uint64_t dropped = 0;

  [[nodiscard]] Nanos nominal_bits(std::uint32_t n) const {
    return can_frame_duration(CanFrameBits{n, 0, 0}, timing);
  }

  void wake() {
    if (busy) return;
    busy = true;
    scheduler.at(scheduler.now(), [this] { arbitrate(); });
  }

  // Arbitration field as the bus compares it, dominant (0) first: base ID, RTR/SRR, IDE,
  // ID extension, RTR (RRS for FD). The smaller key wins.
  static std::uint64_t arbitration_key(const CanFrame& f) {
    const bool remote = f.rtr && !f.fd;
    if (f.extended) {
      return (std::uint64_t{f.id >> 18} << 21) | (1U << 20) | (1U << 19) |
             (std::uint64_t{f.id & 0x3'FFFFU} << 1) | (remote ? 1U : 0U);
    }
    return (std::uint64_t{f.id} << 21) | (remote ? (1U << 20) : 0U);
  }

  void arbitrate() {
    CanNode* winner = nullptr;
    std::uint64_t best = 0;
    for (const auto& node : nodes) {
      if (node->queue_.empty()) continue;
      const std::uint64_t key = arbitration_key(node->queue_.front());
      if (winner == nullptr || key < best) {
        winner = node.get();
        best = key;
      }
    }
    if (winner == nullptr) {
      busy = false;
      return;
    }
    sender = winner;
    current = winner->queue_.front();
    const CanFrameBits bits = can_frame_bits(current);
    if (error && error(current)) {
      const Nanos duration = can_frame_duration(bits, timing);
      // Sent up to the ACK delimiter (all but EOF and intermission), then the error frame.
      const Nanos until_error = duration - nominal_bits(7 + 3);
      scheduler.after(until_error + nominal_bits(6 + 8 + 3), [this] { error_frame_done(); });
      return;
    }
    scheduler.after(can_end_of_frame(bits, timing), [this] { end_of_frame(); });
  }

  void error_frame_done() {
    ++errors;
    sender->tec_ += 8;
    if (sender->tec_ > 255) {
      sender->bus_off_ = true;
      sender->queue_.clear();
    }
    arbitrate(); // the frame is still at the head of its queue: automatic retransmission
  }

  void end_of_frame() {
    CanNode* from = sender;
    from->queue_.pop_front();
    if (from->tec_ > 0) --from->tec_;
    const Nanos t = scheduler.now();
    scheduler.after(nominal_bits(3), [this] { arbitrate(); }); // after the intermission
    if (drop && drop(current)) {
      ++dropped;
      return;
    }
    ++delivered;
    if (trace != nullptr) trace->can(name, t, current);
    const CanFrame frame = current; // a handler may send, which must not disturb this copy
    for (const auto& node : nodes) {
      if (node.get() == from) continue;
      for (const auto& handler : node->handlers_) handler(frame, t);
    }
  }
};

void CanNode::send(const CanFrame& frame) {
  if (bus_off_) return;
  can_check_frame(frame); // now, in the sender's context
  queue_.push_back(frame);
  bus_.wake();
}

CanBus::CanBus(Scheduler& scheduler, std::string name, CanBitTiming timing, TraceRecorder* trace)
    : impl_(std::make_unique<Impl>(scheduler, std::move(name), timing, trace)) {}

CanBus::~CanBus() = default;

const std::string& CanBus::name() const { return impl_->name; }
const CanBitTiming& CanBus::timing() const { return impl_->timing; }

CanPort& CanBus::attach(std::string node_name) {
  impl_->nodes.push_back(std::make_unique<CanNode>(*impl_, std::move(node_name)));
  return *impl_->nodes.back();
}

void CanBus::set_drop(FrameFilter drop) { impl_->drop = std::move(drop); }
void CanBus::set_error(FrameFilter error) { impl_->error = std::move(error); }

std::uint64_t CanBus::frames_delivered() const { return impl_->delivered; }
std::uint64_t CanBus::error_frames() const { return impl_->errors; }
std::uint64_t CanBus::frames_dropped() const { return impl_->dropped; }

namespace {
const CanNode& node_of(const std::vector<std::unique_ptr<CanNode>>& nodes, const CanPort& port) {
  for (const auto& n : nodes) {
    if (n.get() == &port) return *n;
  }
  throw std::invalid_argument("CanBus: port is not attached to this bus");
}
} // namespace

std::uint32_t CanBus::transmit_errors(const CanPort& port) const { return node_of(impl_->nodes, port).tec(); }
bool CanBus::bus_off(const CanPort& port) const { return node_of(impl_->nodes, port).is_bus_off(); }

} // namespace hilrig::virt
