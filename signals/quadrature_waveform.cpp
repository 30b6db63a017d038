#include "signals/quadrature_waveform.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace hilrig::signals {

QuadratureWaveform::QuadratureWaveform(MotionProfile profile, const QuadratureEncoder& encoder, Nanos until)
    : profile_(std::move(profile)), solver_(profile_, encoder, until),
      count_before_head_(solver_.initial_count()) {}

bool QuadratureWaveform::solve_more() {
  if (solved_all_) return false; // asked often past the last edge (a shaft at rest)
  const std::size_t n = solver_.fill(batch_);
  for (std::size_t i = 0; i < n; ++i)
    if (batch_[i].channel != QuadChannel::Z) edges_.push_back(batch_[i]);
  solved_all_ = n == 0;
  return n != 0;
}

std::size_t QuadratureWaveform::first_after(Nanos t) {
  while ((edges_.size() == head_ || edges_.back().time <= t) && solve_more()) {}
  const auto it = std::upper_bound(edges_.begin() + static_cast<std::ptrdiff_t>(head_), edges_.end(), t,
                                   [](Nanos time, const QuadEdge& e) { return time < e.time; });
  return static_cast<std::size_t>(it - edges_.begin());
}

std::int64_t QuadratureWaveform::count_at(Nanos t) {
  const std::size_t i = first_after(t);
  return i == head_ ? count_before_head_ : edges_[i - 1].count;
}

std::int64_t QuadratureWaveform::count_showing(Nanos t, bool a, bool b) {
  std::size_t i = first_after(t - Nanos{1});
  std::int64_t c = i == head_ ? count_before_head_ : edges_[i - 1].count;
  for (;;) {
    if (channel_a(c) == a && channel_b(c) == b) return c;
    if (i == edges_.size() || edges_[i].time != t) break;
    c = edges_[i++].count;
  }
  throw std::logic_error("QuadratureWaveform: the lines show no count of the waveform at this time");
}

Nanos QuadratureWaveform::leaves(Nanos after, std::int64_t lo, std::int64_t hi) {
  for (std::size_t i = first_after(after);; ++i) {
    if (i == edges_.size() && !solve_more()) return Nanos::max();
    if (edges_[i].count < lo || edges_[i].count > hi) return edges_[i].time;
  }
}

void QuadratureWaveform::forget_before(Nanos t) {
  while (head_ < edges_.size() && edges_[head_].time < t) count_before_head_ = edges_[head_++].count;
  if (head_ > 4096 && head_ * 2 > edges_.size()) { // drop what is behind, now and then
    edges_.erase(edges_.begin(), edges_.begin() + static_cast<std::ptrdiff_t>(head_));
    head_ = 0;
  }
}

} // namespace hilrig::signals
