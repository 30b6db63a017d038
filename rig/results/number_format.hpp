#pragma once
// Numbers as a person reads them in report.html: no float noise (800.0000000000018 reads
// 800), times in the unit that fits (ns, µs, ms, s) instead of raw nanoseconds.

#include <optional>
#include <string>

#include "core/time.hpp"

namespace hilrig::rig {

// At most 9 significant digits, trailing zeros dropped: the double's rounding noise goes,
// a value the board could show (a count to 10^-3 at 10^6 counts) stays.
[[nodiscard]] std::string format_number(double v);
// A duration or an instant in nanoseconds, in s, ms, µs or ns (the largest unit with an
// integer part), e.g. "1.5 ms", "750 µs".
[[nodiscard]] std::string format_ns(double ns);
[[nodiscard]] inline std::string format_time(Nanos t) { return format_ns(static_cast<double>(t.count())); }
// v in `digits` significant digits, or as many more (up to 17) as tell it from `beside` when
// the two differ: a value 1 ns beyond its limit (21000.001 us against 21000 us) must not read
// as the limit itself, a board failed at its limit to whoever reads it.
[[nodiscard]] std::string format_number_apart(double v, const std::optional<double>& beside, int digits = 6);
// The limit v lies beyond (upper first), if any: the number a failing value is told apart from.
[[nodiscard]] std::optional<double> limit_beyond(double v, const std::optional<double>& lower,
                                                 const std::optional<double>& upper);
// A value with its unit ("" for a count of things); "us" reads µs. With `beside` (the limit it
// broke) its number is told apart from it (format_number_apart).
[[nodiscard]] std::string format_value(double v, const std::string& unit,
                                       const std::optional<double>& beside = std::nullopt);

} // namespace hilrig::rig
