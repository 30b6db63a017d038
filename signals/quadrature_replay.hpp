#pragma once
// Plays a quadrature trace into a decoder the way a board samples its inputs: all edges
// at one nanosecond are applied together, then the decoder sees the new levels once (so
// edges moved onto the same instant are an illegal transition, as on a real input).

#include <cstddef>

#include "signals/quadrature_decoder.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::signals {

// Calls after(Nanos time, const QuadratureDecoder&) after each instant that has edges.
template <class F> void replay(const QuadratureTrace& trace, QuadratureDecoder& decoder, F&& after) {
  bool a = trace.initial_level(QuadChannel::A);
  bool b = trace.initial_level(QuadChannel::B);
  bool z = trace.initial_z;
  const auto& edges = trace.edges;
  for (std::size_t i = 0; i < edges.size();) {
    const Nanos t = edges[i].time;
    for (; i < edges.size() && edges[i].time == t; ++i) {
      const bool high = edges[i].level == Level::High;
      switch (edges[i].channel) {
      case QuadChannel::A:
        a = high;
        break;
      case QuadChannel::B:
        b = high;
        break;
      case QuadChannel::Z:
        z = high;
        break;
      }
    }
    decoder.update(a, b);
    decoder.index(z);
    after(t, static_cast<const QuadratureDecoder&>(decoder));
  }
}

} // namespace hilrig::signals
