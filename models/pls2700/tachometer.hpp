#pragma once
// The tachometer of one channel (pls2700.md §4.3, model [I]): over each response interval T
// the signed 8192-count motion is summed; at the end of the interval the value becomes
// floor(|count| * 60 / (8192 * T) / resolution) and is held until the next interval ends.
#include <cstdint>

#include "core/time.hpp"

namespace hilrig::models::pls2700 {

inline constexpr std::uint16_t kTachMask = 0x3FFF; // 14-bit field (L1613)

// R-T-1: code 0..4 -> interval (30/60/120/240/240 ms); code 4 reports tenths.
[[nodiscard]] Nanos tach_interval(int code, bool thirty_two_ms);
[[nodiscard]] constexpr bool tach_in_tenths(int code) { return code == 4; }
// Speed in units of the resolution from `counts` (8192 per turn) moved in `interval`.
[[nodiscard]] std::uint16_t tach_value(std::int64_t counts, Nanos interval, bool tenths);

class Tachometer {
public:
  // Starts a new interval at the update sample `start` (the steps added from then on are
  // counted): `window` is how long counts are summed, `scale` the interval the speed is
  // computed for (equal in a correct module).
  void restart(Nanos start, Nanos window, Nanos scale, bool tenths);
  void add(std::int64_t counts) { sum_ += counts; }
  // At an update tick: closes the interval when it is over. True when the value changed.
  bool update(Nanos now);
  [[nodiscard]] std::uint16_t value() const { return value_; }

private:
  Nanos end_{0};
  Nanos window_{1};
  Nanos scale_{1};
  bool tenths_ = false;
  std::int64_t sum_ = 0;
  std::uint16_t value_ = 0;
};

} // namespace hilrig::models::pls2700
