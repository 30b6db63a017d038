#pragma once
// Signal faults on a solved quadrature trace. Each works on the edge list, keeps it in
// time order and keeps every edge a real change of level, so the result plays on a line
// exactly as written. Faulted edges keep `count` = the true encoder count at their time.

#include <cstddef>
#include <cstdint>

#include "core/time.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::signals {

// A pulse of `width` on one channel (A, B or Z) starting at `at`: the line is inverted
// for [at, at + width). A real edge inside the window is inverted with it.
void inject_glitch(QuadratureTrace& trace, QuadChannel channel, Nanos at, Nanos width);

// The A/B edge at `index` (into trace.edges) is lost. A line cannot skip one edge and stay
// a level signal, so the pulse it starts disappears: the channel holds its level until
// its following edge, which is lost too.
void inject_missing_edge(QuadratureTrace& trace, std::size_t index);

// Both channels change at once: the first edge of the other channel (A <-> B) after the
// A/B edge at `index` is moved to the same nanosecond.
void inject_simultaneous_edges(QuadratureTrace& trace, std::size_t index);

// A noise burst: `pulses` glitches on A or B (each channel picked at random) starting
// uniformly in [start, start + length) with widths uniform in [min_width, max_width].
// Deterministic for a seed (std::mt19937_64 with our own mapping to ranges).
struct NoiseBurst {
  Nanos start;
  Nanos length;
  std::size_t pulses = 8;
  Nanos min_width{20};
  Nanos max_width{200};
  std::uint64_t seed = 1;
};
void inject_noise_burst(QuadratureTrace& trace, const NoiseBurst& burst);

// Phase error: every B edge moves by `fraction` of its local quarter period (the time to
// the next A edge when fraction > 0, from the previous one when < 0). |fraction| < 1
// only narrows the A-B spacing; 1 makes B change with A; beyond 1 B passes A and the
// decoded direction flips.
void inject_phase_error(QuadratureTrace& trace, double fraction);

} // namespace hilrig::signals
