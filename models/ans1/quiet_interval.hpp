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
  // Keeps `at - down` .. `at + up`: a run of GMP values found by its distances from `at`.
  void keep_run(std::uint16_t at, std::int64_t down, std::int64_t up) {
    lo = static_cast<std::uint16_t>(std::max<std::int64_t>(lo, at - down));
    hi = static_cast<std::uint16_t>(std::min<std::int64_t>(hi, at + up));
  }
  // Any count change matters.
  void pin(std::uint16_t at) { lo = hi = at; }
};

// How many counts in a row from `count` (not counting it) in direction `step` (+1 or -1) have
// their GMP inside `quiet`, at most one cycle (CPC): the walk
//   k = 0; while (k < CPC && quiet.contains(global_position(count + step * (k + 1), setup))) ++k;
// without a division per count. Over counts whose q = count mod CPC does not roll over, the
// scaled count s = floor(q * FSC / CPC) never decreases, and GMP = (s + SMO) mod FSC is
// s + SMO - m * FSC for one m until s + SMO reaches the next multiple of FSC; so from a count
// inside, every count up to (down to) the first whose s passes the interval's end (start),
// shifted by m * FSC - SMO, is inside too, and the walk jumps there. Each jump reaches a count
// outside, a roll-over of q or of the GMP: a few jumps a cycle.
[[nodiscard]] constexpr std::int64_t counts_inside(std::int64_t count, std::int64_t step,
                                                   const PositionSetup& setup, const QuietInterval& quiet) {
  const std::int64_t cpc = setup.counts_per_cycle;
  const std::int64_t fsc = setup.full_scale_count;
  const std::int64_t offset = setup.scaled_offset;
  std::int64_t k = 1; // the count tested next is count + step * k
  while (k <= cpc) {
    const std::int64_t q = wrap(count + step * k, cpc);
    const std::int64_t t = q * fsc / cpc + offset;
    const std::int64_t gmp = wrap(t, fsc);
    if (gmp < quiet.lo || gmp > quiet.hi) {
      return k - 1;
    }
    const std::int64_t base = t - gmp; // m * FSC
    std::int64_t end = 0;              // the first q in the walk's direction not known inside
    if (step > 0) {
      // Inside while s <= quiet.hi + base - offset (which is below the next multiple of FSC).
      const std::int64_t first_out = quiet.hi + base - offset + 1; // s at or above it: outside
      end = std::min(cpc, (first_out * cpc + fsc - 1) / fsc);      // least q with s >= first_out
      k += end - q;
    } else {
      // Inside while s >= quiet.lo + base - offset (at or above the multiple of FSC).
      const std::int64_t least_in = quiet.lo + base - offset;
      end = least_in <= 0 ? -1 : (least_in * cpc + fsc - 1) / fsc - 1; // greatest q with s < least_in
      k += q - end;
    }
  }
  return cpc;
}

} // namespace hilrig::models::ans1
