#include "signals/ssi_master.hpp"

#include <algorithm>
#include <stdexcept>

namespace hilrig::signals {

SsiMasterParams ssi7361_master(bool clock_500khz) {
  SsiMasterParams p;
  p.clock_hz = clock_500khz ? 500'000.0 : 125'000.0;
  p.frame_bits = 25;
  p.frame_period = clock_500khz ? microseconds(250) : microseconds(500);
  return p;
}

Level LineHistory::level_at(Nanos t) const {
  // First edge strictly after t; the one before it (if any) sets the level.
  const auto it =
      std::upper_bound(edges_.begin(), edges_.end(), t, [](Nanos x, const Edge& e) { return x < e.time; });
  return it == edges_.begin() ? initial_ : std::prev(it)->level;
}

SsiMaster::SsiMaster(SsiMasterParams params) : params_(params) {
  if (!(params_.clock_hz >= 1e3 && params_.clock_hz <= 10e6))
    throw std::invalid_argument("SSI clock must be 1 kHz..10 MHz");
  if (params_.frame_bits < 1 || params_.frame_bits > 32) throw std::invalid_argument("SSI frame_bits 1..32");
  period_ = Nanos::from_seconds(1.0 / params_.clock_hz) + params_.clock_period_error;
  if (period_ < Nanos{2}) throw std::invalid_argument("SSI clock period (with its error) under 2 ns");
  half_ = period_ / 2;
  // The burst ends with R_n at (n - 1/2)T; the next F1 must come after it.
  if (params_.frame_period <= rising_edge(Nanos{0}, params_.frame_bits))
    throw std::invalid_argument("SSI frame period shorter than the clock burst");
}

Nanos SsiMaster::falling_edge(Nanos frame_start, unsigned j) const {
  return frame_start + period_ * static_cast<std::int64_t>(j - 1);
}

Nanos SsiMaster::rising_edge(Nanos frame_start, unsigned k) const {
  return falling_edge(frame_start, k) + half_;
}

Nanos SsiMaster::sample_time(Nanos frame_start, unsigned k) const {
  return frame_start + period_ * static_cast<std::int64_t>(k);
}

void SsiMaster::append_burst(Nanos frame_start, std::vector<Edge>& out) const {
  for (unsigned k = 1; k <= params_.frame_bits; ++k) {
    out.push_back(Edge{falling_edge(frame_start, k), Level::Low});
    out.push_back(Edge{rising_edge(frame_start, k), Level::High});
  }
}

std::vector<Edge> SsiMaster::clock_schedule(Nanos first, std::size_t frames) const {
  std::vector<Edge> out;
  out.reserve(frames * 2 * params_.frame_bits);
  for (std::size_t i = 0; i < frames; ++i)
    append_burst(first + params_.frame_period * static_cast<std::int64_t>(i), out);
  return out;
}

SsiReading SsiMaster::read_frame(const LineHistory& data, Nanos frame_start) const {
  SsiReading r;
  r.frame_start = frame_start;
  r.ready = is_high(data.level_at(frame_start - Nanos{1}));
  for (unsigned k = 1; k <= params_.frame_bits; ++k)
    r.word = (r.word << 1) | (is_high(data.level_at(sample_time(frame_start, k))) ? 1u : 0u);
  r.released = is_high(data.level_at(frame_start + params_.frame_period - Nanos{1}));
  return r;
}

std::vector<SsiReading> SsiMaster::read_frames(const LineHistory& data, Nanos first,
                                               std::size_t frames) const {
  std::vector<SsiReading> out;
  out.reserve(frames);
  for (std::size_t i = 0; i < frames; ++i)
    out.push_back(read_frame(data, first + params_.frame_period * static_cast<std::int64_t>(i)));
  return out;
}

} // namespace hilrig::signals
