#include "models/ans1/setpoint.hpp"

#include <vector>

#include "models/ans1/position.hpp"

namespace hilrig::models::ans1 {

std::int32_t pair_length(const SetpointPair& pair, std::uint16_t fsc) {
  if (!pair.used()) {
    return 0;
  }
  if (pair.from == pair.to) {
    return fsc;
  }
  return static_cast<std::int32_t>(wrap(static_cast<std::int64_t>(pair.to) - pair.from, fsc));
}

bool in_pair(std::uint16_t p, const SetpointPair& pair, std::uint16_t fsc) {
  return pair_on(p, pair, fsc, EdgeShift{});
}

bool stitch_fits(const SetpointPair& pair, std::uint16_t fsc) {
  if (!pair.stitched()) {
    return true;
  }
  return pair_length(pair, fsc) >= 2 * pair.on_stitch + pair.off_stitch;
}

bool stitch_on(std::int32_t d, std::int32_t length, std::int32_t on, std::int32_t off) {
  const std::int32_t period = on + off;
  const std::int32_t whole = (length / period) * period;
  if (d < whole) {
    return d % period < on;
  }
  const std::int32_t remainder = length - whole;
  if (remainder >= on) {
    return d - whole < on; // a full On fits; the rest is Off
  }
  return 2 * remainder >= on; // at least half an On: on to the end (L872), else off (L873)
}

StitchRun stitch_run(std::int32_t d, std::int32_t length, std::int32_t on, std::int32_t off,
                     std::int32_t fsc) {
  if (d >= length) {
    return {length, fsc - 1};
  }
  const std::int32_t period = on + off;
  const std::int32_t whole = (length / period) * period;
  if (d < whole) {
    const std::int32_t base = d - d % period;
    return d - base < on ? StitchRun{base, base + on - 1} : StitchRun{base + on, base + period - 1};
  }
  if (length - whole >= on) { // stitch_on's full On, then Off to the end
    return d - whole < on ? StitchRun{whole, whole + on - 1} : StitchRun{whole + on, length - 1};
  }
  return {whole, length - 1}; // one value to the end
}

PairArc pair_arc(const SetpointPair& pair, std::uint16_t fsc, EdgeShift shift, bool late_wrap_to) {
  if (!pair.used()) {
    return {};
  }
  if (pair.from == pair.to) {
    return {0, fsc}; // on at every position (L1897)
  }
  std::int32_t length = pair_length(pair, fsc);
  if (late_wrap_to && pair.from > pair.to) {
    ++length;
  }
  return {static_cast<std::int64_t>(pair.from) - shift.from, length + shift.from - shift.to};
}

bool pair_on(std::uint16_t p, const SetpointPair& pair, std::uint16_t fsc, EdgeShift shift,
             bool late_wrap_to) {
  if (!pair.used()) {
    return false;
  }
  if (pair.stitched()) {
    const std::int32_t length = pair_length(pair, fsc);
    const auto d =
        static_cast<std::int32_t>(wrap(static_cast<std::int64_t>(p) - pair.from + shift.stitch, fsc));
    return d < length && stitch_on(d, length, pair.on_stitch, pair.off_stitch);
  }
  const PairArc arc = pair_arc(pair, fsc, shift, late_wrap_to);
  if (arc.length <= 0) {
    return false;
  }
  if (arc.length >= fsc) {
    return true;
  }
  return wrap(static_cast<std::int64_t>(p) - arc.start, fsc) < arc.length;
}

bool pairs_overlap(const std::array<SetpointPair, kPairsPerOutput>& pairs, std::uint16_t fsc) {
  std::vector<bool> taken(fsc, false);
  for (const auto& pair : pairs) {
    if (!pair.used()) {
      continue;
    }
    const std::int32_t length = pair_length(pair, fsc);
    for (std::int32_t d = 0; d < length; ++d) {
      const auto p = static_cast<std::size_t>(wrap(static_cast<std::int64_t>(pair.from) + d, fsc));
      if (taken[p]) {
        return true;
      }
      taken[p] = true;
    }
  }
  return false;
}

} // namespace hilrig::models::ans1
