#include "models/ans1/positions_fit.hpp"

#include <cstdlib>

#include "models/ans1/setpoint.hpp"

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] bool below(std::uint16_t position, std::uint16_t fsc) { return position < fsc; }

[[nodiscard]] bool output_fits(const OutputSetup& o, std::uint16_t fsc) {
  for (const SetpointPair& pair : o.pairs) {
    if (!below(pair.from, fsc) || !below(pair.to, fsc) || !below(pair.on_stitch, fsc) ||
        !below(pair.off_stitch, fsc)) {
      return false;
    }
    if (pair.used() && !stitch_fits(pair, fsc)) return false;
  }
  return std::abs(o.ls_offset) < fsc && below(o.ls_preset_value, fsc) && below(o.window_low, fsc) &&
         below(o.window_high, fsc) && !pairs_overlap(o.pairs, fsc);
}
} // namespace

bool positions_fit(const Ans1Setup& setup, std::uint16_t fsc) {
  for (const OutputSetup& o : setup.outputs) {
    if (!output_fits(o, fsc)) return false;
  }
  for (const DieMonitorSetup& m : setup.monitors.die.monitors) {
    for (const DieWindow& w : m.windows) {
      if (!below(w.leading, fsc) || !below(w.trailing, fsc)) return false;
    }
  }
  const ShiftRegisterSetup& sr = setup.shift_register;
  return below(sr.window_from, fsc) && below(sr.window_to, fsc) && below(sr.shift_position, fsc) &&
         below(setup.monitors.production.increment_position, fsc);
}

} // namespace hilrig::models::ans1
