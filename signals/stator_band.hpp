#pragma once
// The fault band a resolver board judges its demodulated stator amplitude by (stator /
// reference): the ANS1's resolver_min_ratio .. resolver_max_ratio and the Series 2700's
// min_stator_ratio .. max_stator_ratio. The band is closed: a transducer exactly at a limit is
// good. The ratio of two sampled sinusoids carries a few ulps of rounding (cos 60 deg reads
// 0.49999999999999994 at some angles), so a ratio within a relative kStatorRatioSlack of a
// limit counts as at it, not past it.

namespace hilrig::signals {

inline constexpr double kStatorRatioSlack = 1e-9;

[[nodiscard]] constexpr bool stator_ratio_in_band(double ratio, double min_ratio, double max_ratio) {
  return ratio >= min_ratio * (1.0 - kStatorRatioSlack) && ratio <= max_ratio * (1.0 + kStatorRatioSlack);
}

} // namespace hilrig::signals
