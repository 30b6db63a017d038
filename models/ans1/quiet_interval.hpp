#pragma once
// Exact scan skipping while the encoder moves (docs/virtual-time.md, "Motion"): the GMP values
// around the present one over which every position-dependent condition a scan evaluates keeps
// its present value and no position mark a scan watches for is crossed. Linear (a roll-over
// through 0 leaves it) and shorter than half the FSC, so that two GMP values inside it never
// read as a forward crossing of anything outside it.
#include <algorithm>
#include <cstdint>

#include "models/ans1/position.hpp"

namespace hilrig::models::ans1 {

struct QuietInterval {
  std::uint16_t lo = 0;
  std::uint16_t hi = 0;

  // Everything from 0 to FSC-1 but a half-cycle around `at`: the widest interval allowed.
  [[nodiscard]] static QuietInterval around(std::uint16_t at, std::uint16_t fsc) {
    const std::int32_t reach = (fsc - 1) / 4; // hi - lo <= (FSC-1)/2
    return {static_cast<std::uint16_t>(std::max<std::int32_t>(0, at - reach)),
            static_cast<std::uint16_t>(std::min<std::int32_t>(fsc - 1, at + reach))};
  }
  [[nodiscard]] bool contains(std::uint16_t gmp) const { return lo <= gmp && gmp <= hi; }

  // Keeps the run around `at` over which membership of the arc {p : (p - start) mod FSC <
  // length} stays what it is at `at`. An empty or whole arc never changes.
  void keep_arc(std::uint16_t at, std::int64_t start, std::int64_t length, std::uint16_t fsc) {
    if (length <= 0 || length >= fsc) {
      return;
    }
    const std::int64_t u = wrap(static_cast<std::int64_t>(at) - start, fsc);
    const std::int64_t down = u < length ? u : u - length;
    const std::int64_t up = u < length ? length - 1 - u : fsc - 1 - u;
    lo = static_cast<std::uint16_t>(std::max<std::int64_t>(lo, at - down));
    hi = static_cast<std::uint16_t>(std::min<std::int64_t>(hi, at + up));
  }
  // Keeps `mark` out of (lo, hi]: moving forward inside never reaches it (from excluded).
  void keep_before_mark(std::uint16_t at, std::uint16_t mark) {
    if (mark <= at) {
      lo = std::max(lo, mark);
    } else {
      hi = std::min(hi, static_cast<std::uint16_t>(mark - 1));
    }
  }
  // Any count change matters.
  void pin(std::uint16_t at) { lo = hi = at; }
};

} // namespace hilrig::models::ans1
