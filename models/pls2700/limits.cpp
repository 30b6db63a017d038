#include "models/pls2700/limits.hpp"

#include <cmath>

#include "models/pls2700/position.hpp"

namespace hilrig::models::pls2700 {

bool pair_on(const SetpointPair& pair, int mp, int scale_factor, double s_on, double s_off,
             const WindowRules& rules) {
  int base = pair.off - pair.on;
  if (base == 0) {
    return rules.equal_pair_full_turn;
  }
  if (base < 0) {
    if (!rules.wrap_pairs) {
      return false;
    }
    base += scale_factor;
  }
  const double sf = static_cast<double>(scale_factor);
  const double length = static_cast<double>(base) + s_on - s_off;
  if (length <= 0.0) {
    return false;
  }
  if (length >= sf) {
    return true;
  }
  double from_on = std::fmod(static_cast<double>(mp) - (static_cast<double>(pair.on) - s_on), sf);
  if (from_on < 0.0) {
    from_on += sf;
  }
  return from_on < length;
}

bool output_on(const OutputSetup& output, int mp, int scale_factor, double s_on, double s_off,
               const WindowRules& rules) {
  for (int k = 0; k < output.pair_count; ++k) {
    if (pair_on(output.pairs[static_cast<std::size_t>(k)], mp, scale_factor, s_on, s_off, rules)) {
      return true;
    }
  }
  return false;
}

bool cycle_output_on(const OutputSetup& output, int ls, int cycle_length, double s_on, double s_off,
                     bool anticipate) {
  const double pos = static_cast<double>(ls);
  for (int k = 0; k < output.pair_count; ++k) {
    const SetpointPair& p = output.pairs[static_cast<std::size_t>(k)];
    if (p.on >= p.off) {
      continue; // ON == OFF: no window (ON > OFF is refused, R-18-2)
    }
    const double e_on = static_cast<double>(p.on) - s_on;
    const double e_off = static_cast<double>(p.off) - s_off;
    if (pos >= e_on && pos < e_off) {
      return true;
    }
    if (anticipate && e_on < 0.0 && pos >= static_cast<double>(cycle_length) + e_on) {
      return true;
    }
  }
  return false;
}

void HoleTable::mark(const SetpointPair& pair, int scale_factor, bool value) {
  // A stored pair beyond the present SF (R-SF-3 [X]) never matches: nothing to mark.
  if (pair.on == pair.off || pair.on >= scale_factor || pair.off >= scale_factor) {
    return;
  }
  const int length = mod(pair.off - pair.on, scale_factor);
  for (int i = 0; i < length; ++i) {
    const int p = (pair.on + i) % scale_factor;
    if (p < kPositions) {
      holes_.set(static_cast<std::size_t>(p), value);
    }
  }
}

} // namespace hilrig::models::pls2700
