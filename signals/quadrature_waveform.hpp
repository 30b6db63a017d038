#pragma once
// A quadrature encoder's A/B pair as a waveform (docs/virtual-time.md, "Lines carry waveforms"):
// a consumer that only samples the count asks for the count at a time and for the first time
// the count leaves a range, instead of taking every edge as an event. The answers come from
// the same edge solver, over the same profile, encoder and end, that times the edges the rig
// plays on the lines, so they are what replaying those edges gives, to the nanosecond.
//
// Times asked move forward with the run: edges before forget_before()'s horizon are dropped,
// so the memory held is the edges between the horizon and the latest time asked about.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "signals/motion_profile.hpp"
#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_encoder.hpp"

namespace hilrig::signals {

class QuadratureWaveform {
public:
  // Edges of `profile` before `until` (QuadratureEdgeSolver's); keeps its own copy of it.
  QuadratureWaveform(MotionProfile profile, const QuadratureEncoder& encoder, Nanos until);
  QuadratureWaveform(const QuadratureWaveform&) = delete;
  QuadratureWaveform& operator=(const QuadratureWaveform&) = delete;

  // The count after every edge at or before t (t no earlier than the horizon minus 1 ns).
  [[nodiscard]] std::int64_t count_at(Nanos t);
  // The count the lines show at t when they read a and b (levels after some of the edges at
  // t, in their order: a consumer running between them sees only those before it).
  // Throws std::logic_error when no count the edges at t pass through shows those levels.
  [[nodiscard]] std::int64_t count_showing(Nanos t, bool a, bool b);
  // The time of the first edge after `after` whose count is outside [lo, hi];
  // Nanos::max() when the motion has no such edge.
  [[nodiscard]] Nanos leaves(Nanos after, std::int64_t lo, std::int64_t hi);
  // No time before t - 1 ns is asked about again.
  void forget_before(Nanos t);

private:
  // The index of the first held edge later than t, solving ahead until one is or none is left.
  [[nodiscard]] std::size_t first_after(Nanos t);
  bool solve_more();

  MotionProfile profile_;
  QuadratureEdgeSolver solver_;
  std::vector<QuadEdge> edges_; // A/B edges from head_ on, in time order
  std::size_t head_ = 0;
  bool solved_all_ = false;
  std::array<QuadEdge, 256> batch_{};
  std::int64_t count_before_head_ = 0;
};

} // namespace hilrig::signals
