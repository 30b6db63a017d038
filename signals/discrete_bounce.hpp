#pragma once
// Contact bounce: a contact that closes (or opens) at t touches, reopens `bounces` times
// and settles, all inside `window`. That is 2·bounces + 1 edges: the first touch at t,
// then 2·bounces gaps (reopen, touch again, ...), the last edge being the settle at or
// before t + window.
//
// The gaps are given (`widths`, 2·bounces of them) or drawn from a seed: std::mt19937_64
// mapped to ranges by our own arithmetic (not std::uniform_*_distribution), so a seed
// gives the same bounce on every standard library.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig::signals {

struct ContactBounce {
  Nanos window;              // the settle edge is at or before t + window
  std::size_t bounces = 0;   // reopenings before the contact settles
  std::vector<Nanos> widths; // given gaps: empty, or exactly 2·bounces of them
  std::uint64_t seed = 0;    // for drawn gaps
  Nanos min_width{1};        // every drawn gap is at least this
};

// The edges of one bounce, starting at t and settling at `target`.
[[nodiscard]] std::vector<Edge> bounce_edges(Nanos t, Level target, const ContactBounce& bounce);

// The 2·bounces gaps drawn for a seed: each min_width plus a share of the window's spare
// time proportional to a 53-bit draw, so their sum never exceeds the window.
[[nodiscard]] std::vector<Nanos> draw_bounce_gaps(const ContactBounce& bounce);

} // namespace hilrig::signals
