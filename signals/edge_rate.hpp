#pragma once
// Edge-rate limits: does a profile ask an encoder input for more than its maximum input
// frequency (e.g. the AMCI 4501's 250 kHz)? The frequency of one channel is the count
// rate / 4 (a full A or B cycle is four X4 counts).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/time.hpp"
#include "signals/motion_profile.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::signals {

enum class RateLimitAction : std::uint8_t { Warn, Fail };

struct EdgeRateViolation {
  std::size_t segment = 0; // index into profile.segments()
  Nanos time;              // first instant in the segment above the limit
  double channel_hz = 0;   // the segment's peak channel frequency
  double count_rate = 0;   // the same as X4 counts/s
};

struct EdgeRateError : std::runtime_error {
  explicit EdgeRateError(const std::string& what, EdgeRateViolation v)
      : std::runtime_error(what), violation(v) {}
  EdgeRateViolation violation;
};

// One entry per segment whose channel frequency exceeds max_channel_hz (closed form:
// velocity is linear in a segment). Segments beyond `until` are not checked.
[[nodiscard]] std::vector<EdgeRateViolation> find_edge_rate_violations(const MotionProfile& profile,
                                                                       const QuadratureEncoder& encoder,
                                                                       double max_channel_hz,
                                                                       Nanos until = Nanos::max());

// Warn: returns the violations for the caller to report. Fail: throws EdgeRateError naming
// the first one (time and rate) when there is any.
std::vector<EdgeRateViolation> check_edge_rate(const MotionProfile& profile, const QuadratureEncoder& encoder,
                                               double max_channel_hz, RateLimitAction action,
                                               Nanos until = Nanos::max());

[[nodiscard]] std::string describe(const EdgeRateViolation& v);

// On a finished edge list (after faults, say): the first pair of consecutive edges on one
// channel closer than half a period at max_channel_hz, reported as the rate that spacing
// implies (1 / (2·spacing)) at the later edge's time.
struct EdgeSpacingViolation {
  QuadChannel channel = QuadChannel::A;
  Nanos time;
  Nanos spacing;
  double channel_hz = 0;
};
[[nodiscard]] std::optional<EdgeSpacingViolation> first_spacing_violation(const QuadratureTrace& trace,
                                                                          double max_channel_hz);

// The smallest time between an A/B edge and the next edge on the other channel: a quarter
// period for a clean encoder at constant speed; a phase error narrows it.
[[nodiscard]] std::optional<Nanos> min_phase_separation(const QuadratureTrace& trace);

} // namespace hilrig::signals
