#include "models/resolver_emulator/resolver_emulator.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "signals/resolver.hpp"
#include "signals/resolver_frames.hpp"

namespace hilrig::models::resolver_emulator {

namespace {

// Frames kept for readers sampling a little in the past (an ADC that reads a window).
constexpr std::size_t kHistory = 16;

signals::ResolverParams carrier_params(const ResolverEmulatorParams& p) {
  signals::ResolverParams r;
  r.excitation_hz = p.excitation_hz;
  r.excitation_amplitude = p.excitation_amplitude;
  r.excitation_phase_rad = p.excitation_phase_rad;
  r.transformation_ratio = p.transformation_ratio;
  return r;
}

double wrap(double turns) { return turns - std::floor(turns); }

} // namespace

struct ResolverEmulator::State {
  explicit State(const ResolverEmulatorParams& p)
      : params(p), carrier(carrier_params(p), [](Nanos) { return 0.0; }),
        timeout_after(p.frame_period * static_cast<std::int64_t>(p.timeout_periods)) {}

  ResolverEmulatorParams params;
  // Only its reference is used: the exact carrier (phase reduced per period for long runs).
  signals::Resolver carrier;
  Nanos timeout_after;
  std::array<ResolverAnchor, kHistory> history{};
  std::size_t held = 0; // frames in history
  std::size_t next = 0; // slot of the next frame
  ResolverEmulatorCounters counters;
  bool timed_out = false;
  std::optional<std::uint8_t> last_sequence;

  void push(const ResolverAnchor& a) {
    history[next] = a;
    next = (next + 1) % kHistory;
    if (held < kHistory) ++held;
  }
  [[nodiscard]] const ResolverAnchor* newest() const {
    return held == 0 ? nullptr : &history[(next + kHistory - 1) % kHistory];
  }
  // The frame in force at t: the newest received at or before t.
  [[nodiscard]] const ResolverAnchor* anchor_at(Nanos t) const {
    for (std::size_t i = 1; i <= held; ++i) {
      const ResolverAnchor& a = history[(next + kHistory - i) % kHistory];
      if (a.received <= t) return &a;
    }
    return nullptr;
  }
  // The anchor driving the stators at t, or null (no frame, invalid, timed out).
  [[nodiscard]] const ResolverAnchor* driving(Nanos t) const {
    const ResolverAnchor* a = anchor_at(t);
    if (a == nullptr || !a->valid || t - a->received >= timeout_after) return nullptr;
    return a;
  }
  [[nodiscard]] static double angle(const ResolverAnchor& a, Nanos t) {
    return a.angle_turns + a.speed_turns_per_s * (t - a.received).seconds();
  }
  [[nodiscard]] double sin_out(Nanos t) const {
    const ResolverAnchor* a = driving(t);
    if (a == nullptr || a->sin_open) return 0.0;
    return params.transformation_ratio * carrier.reference(t) *
           std::sin(2.0 * std::numbers::pi * angle(*a, t));
  }
  [[nodiscard]] double cos_out(Nanos t) const {
    const ResolverAnchor* a = driving(t);
    if (a == nullptr || a->cos_open) return 0.0;
    return params.transformation_ratio * carrier.reference(t) *
           std::cos(2.0 * std::numbers::pi * angle(*a, t));
  }
};

ResolverEmulator::ResolverEmulator(Scheduler& scheduler, CanPort& port, ResolverEmulatorParams params)
    : scheduler_(scheduler), self_(std::make_shared<ResolverEmulator*>(this)) {
  if (params.channel > 15) throw std::invalid_argument("resolver emulator: channel must be 0..15");
  if (params.frame_period <= Nanos::zero())
    throw std::invalid_argument("resolver emulator: frame period must be > 0");
  if (params.timeout_periods == 0)
    throw std::invalid_argument("resolver emulator: timeout_periods must be > 0");
  state_ = std::make_shared<State>(params); // the carrier checks excitation, amplitude and TR
  port.on_receive([self = self_](const CanFrame& frame, Nanos at) {
    if (*self != nullptr) (*self)->receive(frame, at);
  });
}

ResolverEmulator::~ResolverEmulator() {
  *self_ = nullptr;
  scheduler_.cancel(timeout_event_);
}

const ResolverEmulatorParams& ResolverEmulator::params() const { return state_->params; }
const ResolverEmulatorCounters& ResolverEmulator::counters() const { return state_->counters; }
bool ResolverEmulator::timed_out() const { return state_->timed_out; }

std::optional<ResolverAnchor> ResolverEmulator::last_frame() const {
  const ResolverAnchor* a = state_->newest();
  if (a == nullptr) return std::nullopt;
  return *a;
}

void ResolverEmulator::on_timeout(TimeoutHandler handler) { timeout_handler_ = std::move(handler); }
void ResolverEmulator::on_frame(FrameHandler handler) { frame_handler_ = std::move(handler); }

void ResolverEmulator::receive(const CanFrame& frame, Nanos at) {
  State& s = *state_;
  if (frame.id != signals::kResolverAngleId || frame.extended) {
    ++s.counters.other_ids;
    return;
  }
  const auto decoded = signals::decode_resolver_angle(frame);
  if (!decoded) {
    ++s.counters.bad_frames;
    return;
  }
  if (decoded->channel != s.params.channel) {
    ++s.counters.other_channel;
    return;
  }
  ++s.counters.frames;
  const auto sequence = static_cast<std::uint8_t>(decoded->sequence & 0xFu);
  if (s.last_sequence) {
    const auto expected = static_cast<std::uint8_t>((*s.last_sequence + 1u) & 0xFu);
    if (sequence != expected) {
      ++s.counters.sequence_gaps;
      s.counters.lost_frames += static_cast<std::uint64_t>((sequence - expected) & 0xF);
    }
  }
  s.last_sequence = sequence;
  s.timed_out = false;
  s.push(ResolverAnchor{at, wrap(decoded->angle_turns), decoded->speed_turns_per_s, decoded->valid,
                        decoded->sin_open, decoded->cos_open});
  arm_timeout(at);
  if (frame_handler_) frame_handler_();
}

void ResolverEmulator::arm_timeout(Nanos last_frame) {
  scheduler_.cancel(timeout_event_);
  const Nanos deadline = last_frame + state_->timeout_after;
  timeout_event_ = scheduler_.at(deadline, [this, deadline] {
    timeout_event_ = EventId{};
    State& s = *state_;
    ++s.counters.timeouts;
    s.timed_out = true;
    // Frames after a timeout start a new sequence: the loss is already reported.
    s.last_sequence.reset();
    if (timeout_handler_) timeout_handler_(deadline);
  });
}

std::optional<double> ResolverEmulator::angle_turns(Nanos t) const {
  const ResolverAnchor* a = state_->driving(t);
  if (a == nullptr) return std::nullopt;
  return wrap(State::angle(*a, t));
}

double ResolverEmulator::reference(Nanos t) const { return state_->carrier.reference(t); }
double ResolverEmulator::sin(Nanos t) const { return state_->sin_out(t); }
double ResolverEmulator::cos(Nanos t) const { return state_->cos_out(t); }

Waveform ResolverEmulator::reference_waveform() const {
  return [s = state_](Nanos t) { return s->carrier.reference(t); };
}
Waveform ResolverEmulator::sin_waveform() const {
  return [s = state_](Nanos t) { return s->sin_out(t); };
}
Waveform ResolverEmulator::cos_waveform() const {
  return [s = state_](Nanos t) { return s->cos_out(t); };
}

} // namespace hilrig::models::resolver_emulator
