#include "models/resolver_emulator/angle_streamer.hpp"

#include <stdexcept>
#include <utility>

#include "signals/resolver_frames.hpp"

namespace hilrig::models::resolver_emulator {

CanFrame angle_frame(const signals::MotionProfile& profile, const AngleStreamParams& params, Nanos t,
                     std::uint64_t n, AngleFlags flags) {
  const Nanos at = t + params.lead;
  signals::ResolverAngleFrame f;
  f.channel = params.channel;
  f.angle_turns = profile.position(at) / params.units_per_turn;
  f.speed_turns_per_s = profile.velocity(at) / params.units_per_turn;
  f.sequence = static_cast<std::uint8_t>(n & 0xFu);
  f.valid = flags.valid;
  f.sin_open = flags.sin_open;
  f.cos_open = flags.cos_open;
  return signals::encode(f);
}

AngleStreamer::AngleStreamer(Scheduler& scheduler, CanPort& port, signals::MotionProfile profile,
                             AngleStreamParams params)
    : scheduler_(scheduler), port_(port), profile_(std::move(profile)), params_(params) {
  if (params_.period <= Nanos::zero()) throw std::invalid_argument("angle streamer: period must be > 0");
  if (!(params_.units_per_turn > 0.0))
    throw std::invalid_argument("angle streamer: units_per_turn must be > 0");
  if (params_.channel > 15) throw std::invalid_argument("angle streamer: channel must be 0..15");
}

AngleStreamer::~AngleStreamer() { stop(); }

void AngleStreamer::start(Nanos first) {
  stop();
  next_ = scheduler_.at(first, [this, first] { send_at(first); });
}

void AngleStreamer::stop() {
  scheduler_.cancel(next_);
  next_ = EventId{};
}

void AngleStreamer::send_at(Nanos t) {
  const CanFrame frame = angle_frame(profile_, params_, t, sent_, flags_);
  ++sent_;
  const Nanos next = t + params_.period;
  next_ = scheduler_.at(next, [this, next] { send_at(next); });
  port_.send(frame);
}

} // namespace hilrig::models::resolver_emulator
