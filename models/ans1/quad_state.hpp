#pragma once
// Internal to the ANS1 model (ans1.cpp, scan_skipping.cpp): how the encoder's count reaches it.
#include <cstdint>

#include "core/line.hpp"
#include "models/ans1/ans1.hpp"
#include "signals/quadrature_decoder.hpp"
#include "signals/quadrature_waveform.hpp"

namespace hilrig::models::ans1 {

// The encoder decoder is fed from edge handlers the bus keeps (or the count is sampled from
// the lines' waveform, Ans1Pins::quad_waveform); sharing it keeps those
// handlers safe should the bus outlive the device. A count edge wakes a skipping scan when
// the GMP leaves the quiet interval (scan_skipping.cpp).
struct Ans1::QuadState {
  signals::QuadratureDecoder decoder{signals::CountMode::X4};
  LineInput* a = nullptr;
  LineInput* b = nullptr;
  Ans1* device = nullptr;
  // A sampled encoder: the count is the waveform's as the lines show it now, less its value
  // when the decoder would have started from 0 (attach, power-up).
  signals::QuadratureWaveform* waveform = nullptr;
  std::int64_t base = 0;
  void edge() {
    const std::int64_t before = decoder.count();
    decoder.update(a != nullptr && is_high(a->level()), b != nullptr && is_high(b->level()));
    device->count_edge(before);
  }
  [[nodiscard]] std::int64_t shown(Nanos now) const {
    return waveform->count_showing(now, is_high(a->level()), is_high(b->level()));
  }
  [[nodiscard]] std::int64_t count(Nanos now) const {
    return waveform != nullptr ? shown(now) - base : decoder.count();
  }
  // Restarts the count at 0 from the lines' present state: power-up is not a count.
  void restart(Nanos now) {
    decoder = signals::QuadratureDecoder(signals::CountMode::X4, a != nullptr && is_high(a->level()),
                                         b != nullptr && is_high(b->level()));
    if (waveform != nullptr) base = shown(now);
  }
};

} // namespace hilrig::models::ans1
