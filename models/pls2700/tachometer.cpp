#include "models/pls2700/tachometer.hpp"

#include <algorithm>

#include "models/pls2700/position.hpp"

namespace hilrig::models::pls2700 {

Nanos tach_interval(int code, bool thirty_two_ms) {
  switch (code) {
  case 0:
    return thirty_two_ms ? milliseconds(32) : milliseconds(30);
  case 1:
    return milliseconds(60);
  case 2:
    return milliseconds(120);
  default:
    return milliseconds(240);
  }
}

std::uint16_t tach_value(std::int64_t counts, Nanos interval, bool tenths) {
  const std::int64_t magnitude = counts < 0 ? -counts : counts;
  // rpm = counts * 60 / (8192 * T), rounded to the nearest unit of the resolution; in integers
  // with T in ns. Rounded, not floored [I]: the spec page gives the range as 1..2000 RPM
  // (L479-L480), and a steady 1 RPM counts 4.1 counts in 30 ms, 4 or 5 by the phase: floored,
  // 0.977 would read 0 below the stated range, and a steady 100 RPM 99 every other interval.
  const std::int64_t numerator = magnitude * 60'000'000'000LL * (tenths ? 10 : 1);
  const std::int64_t denominator = kInternalCounts * interval.count();
  const std::int64_t value = (2 * numerator + denominator) / (2 * denominator);
  return static_cast<std::uint16_t>(std::min<std::int64_t>(value, kTachMask));
}

void Tachometer::restart(Nanos start, Nanos window, Nanos scale, bool tenths) {
  end_ = start + window;
  window_ = window;
  scale_ = scale;
  tenths_ = tenths;
  sum_ = 0;
}

bool Tachometer::update(Nanos now) {
  if (now < end_) {
    return false;
  }
  const std::uint16_t before = value_;
  value_ = tach_value(sum_, scale_, tenths_);
  sum_ = 0;
  end_ += window_;
  return value_ != before;
}

} // namespace hilrig::models::pls2700
