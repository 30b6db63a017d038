#include "models/resolver_emulator/angle_streamer.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "signals/resolver_frames.hpp"

namespace hilrig::models::resolver_emulator {

namespace {
constexpr double kAngleCode = 1.0 / 16'777'216.0; // the angle field's LSB, turns (2^-24)
} // namespace

CanFrame angle_frame(const ShaftSample& shaft, const AngleStreamParams& params, std::uint64_t n,
                     AngleFlags flags) {
  signals::ResolverAngleFrame f;
  f.channel = params.channel;
  f.angle_turns = shaft.position / params.units_per_turn;
  f.speed_turns_per_s = shaft.velocity / params.units_per_turn;
  f.sequence = static_cast<std::uint8_t>(n & 0xFu);
  f.valid = flags.valid;
  f.sin_open = flags.sin_open;
  f.cos_open = flags.cos_open;
  return signals::encode(f);
}

CanFrame angle_frame(const signals::MotionProfile& profile, const AngleStreamParams& params, Nanos t,
                     std::uint64_t n, AngleFlags flags) {
  const Nanos at = t + params.lead;
  return angle_frame(ShaftSample{profile.position(at), profile.velocity(at)}, params, n, flags);
}

AngleStreamer::AngleStreamer(Scheduler& scheduler, CanPort& port, signals::MotionProfile profile,
                             AngleStreamParams params)
    : AngleStreamer(
          scheduler, port,
          [p = std::make_shared<const signals::MotionProfile>(std::move(profile))](Nanos t) {
            return ShaftSample{p->position(t), p->velocity(t)};
          },
          params) {}

AngleStreamer::AngleStreamer(Scheduler& scheduler, CanPort& port, ShaftSource shaft, AngleStreamParams params)
    : scheduler_(scheduler), port_(port), shaft_(std::move(shaft)), params_(params) {
  if (!shaft_) throw std::invalid_argument("angle streamer: no shaft");
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

void AngleStreamer::lead_by_transport(TransportDelay delay, std::vector<Nanos> possible) {
  if (delay && possible.empty()) throw std::invalid_argument("angle streamer: no possible transport delay");
  transport_ = std::move(delay);
  possible_ = std::move(possible);
  if (!possible_.empty()) last_delay_ = possible_.front();
}

// A frame built for delay d whose own delay is d. Tried: each possible delay, and for each the
// angle's code at or above the shaft (a board reading a shaft that stands exactly on one of its
// counts reads that count) and up to 15 codes above it (1/2^24 turn each: 15 are 9e-7 turn,
// 1/270 of a 12-bit count): the stuff bits change with the code. Consecutive
// frames mostly take the same time on the bus, so the last frame's delay is tried first, and a
// frame's own delay next. No match at all: the nearest miss.
CanFrame AngleStreamer::frame_at(Nanos t) {
  if (!transport_) return angle_frame(shaft_(t + params_.lead), params_, sent_, flags_);
  CanFrame nearest;
  Nanos miss = Nanos::max();
  // The shaft is read once per delay tried, and each (delay, code) frame's own delay found
  // once: a frame tried again changes nothing (its miss is no nearer than the nearest's).
  tries_.clear();
  const auto tried = [&](Nanos delay) -> DelayTry& {
    for (DelayTry& d : tries_)
      if (d.delay == delay) return d;
    DelayTry& d = tries_.emplace_back();
    d.delay = delay;
    d.shaft = shaft_(t + params_.lead + delay);
    d.code = std::ceil(d.shaft.position / params_.units_per_turn / kAngleCode);
    return d;
  };
  const auto build = [&](Nanos delay, int nudge) {
    DelayTry& d = tried(delay);
    const auto bit = static_cast<std::uint16_t>(1U << static_cast<unsigned>(nudge));
    if ((d.known & bit) != 0) return d.own[static_cast<std::size_t>(nudge)];
    ShaftSample shaft = d.shaft;
    shaft.position = (d.code + nudge) * kAngleCode * params_.units_per_turn;
    const CanFrame frame = angle_frame(shaft, params_, sent_, flags_);
    const Nanos own = transport_(frame);
    d.own[static_cast<std::size_t>(nudge)] = own;
    d.known = static_cast<std::uint16_t>(d.known | bit);
    const Nanos off = own > delay ? own - delay : delay - own;
    if (off < miss) {
      nearest = frame;
      miss = off;
      last_delay_ = delay;
    }
    return own;
  };
  for (int nudge = 0; nudge < kNudges && miss != Nanos{0}; ++nudge) {
    Nanos delay = last_delay_;
    for (int step = 0; step < 3 && miss != Nanos{0}; ++step) delay = build(delay, nudge);
  }
  for (int nudge = 0; nudge < kNudges && miss != Nanos{0}; ++nudge)
    for (std::size_t i = 0; i < possible_.size() && miss != Nanos{0}; ++i) (void)build(possible_[i], nudge);
  return nearest;
}

void AngleStreamer::send_at(Nanos t) {
  const CanFrame frame = frame_at(t);
  ++sent_;
  const Nanos next = t + params_.period;
  next_ = scheduler_.at(next, [this, next] { send_at(next); });
  port_.send(frame);
}

} // namespace hilrig::models::resolver_emulator
