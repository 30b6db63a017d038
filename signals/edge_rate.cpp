#include "signals/edge_rate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hilrig::signals {

std::vector<EdgeRateViolation> find_edge_rate_violations(const MotionProfile& profile,
                                                         const QuadratureEncoder& encoder,
                                                         double max_channel_hz, Nanos until) {
  std::vector<EdgeRateViolation> found;
  const double cpu = std::abs(encoder.counts_per_unit());
  // Profile speed at which one channel reaches max_channel_hz.
  const double limit = 4.0 * max_channel_hz / cpu;
  const auto& segments = profile.segments();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (s.start >= until) break;
    const Nanos end = std::min(s.end(), until);
    const double span = (end - s.start).seconds();
    const double v0 = s.velocity;
    const double v1 = s.velocity + s.acceleration * span;
    const double peak = std::max(std::abs(v0), std::abs(v1)); // |v| is largest at an end
    if (peak <= limit) continue;
    double first = 0.0; // seconds into the segment
    if (std::abs(v0) <= limit) {
      // |v0 + a·t| first reaches the limit on the side the segment heads to.
      const double target = v1 > 0 ? limit : -limit;
      first = (target - v0) / s.acceleration;
    }
    found.push_back(EdgeRateViolation{i, s.start + Nanos::from_seconds(first), peak * cpu / 4.0, peak * cpu});
  }
  return found;
}

std::string describe(const EdgeRateViolation& v) {
  std::array<char, 160> text{};
  std::snprintf(text.data(), text.size(),
                "edge rate %.1f Hz per channel (%.1f counts/s) at t = %lld ns, segment %zu", v.channel_hz,
                v.count_rate, static_cast<long long>(v.time.count()), v.segment);
  return text.data();
}

std::vector<EdgeRateViolation> check_edge_rate(const MotionProfile& profile, const QuadratureEncoder& encoder,
                                               double max_channel_hz, RateLimitAction action, Nanos until) {
  auto found = find_edge_rate_violations(profile, encoder, max_channel_hz, until);
  if (action == RateLimitAction::Fail && !found.empty())
    throw EdgeRateError("input frequency limit exceeded: " + describe(found.front()), found.front());
  return found;
}

std::optional<EdgeSpacingViolation> first_spacing_violation(const QuadratureTrace& trace,
                                                            double max_channel_hz) {
  const Nanos min_spacing = Nanos::from_seconds(0.5 / max_channel_hz);
  std::array<Nanos, 3> last{Nanos::min(), Nanos::min(), Nanos::min()};
  for (const QuadEdge& e : trace.edges) {
    const auto ch = static_cast<std::size_t>(e.channel);
    if (last[ch] != Nanos::min() && e.time - last[ch] < min_spacing) {
      const Nanos spacing = e.time - last[ch];
      const double hz =
          spacing > Nanos::zero() ? 0.5 / spacing.seconds() : std::numeric_limits<double>::infinity();
      return EdgeSpacingViolation{e.channel, e.time, spacing, hz};
    }
    last[ch] = e.time;
  }
  return std::nullopt;
}

std::optional<Nanos> min_phase_separation(const QuadratureTrace& trace) {
  std::optional<Nanos> best;
  const QuadEdge* previous = nullptr;
  for (const QuadEdge& e : trace.edges) {
    if (e.channel == QuadChannel::Z) continue;
    if (previous != nullptr && previous->channel != e.channel) {
      const Nanos gap = e.time - previous->time;
      if (!best || gap < *best) best = gap;
    }
    previous = &e;
  }
  return best;
}

} // namespace hilrig::signals
