#include "models/pls2700/params_check.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numeric>

namespace hilrig::models::pls2700 {

namespace {

// The shortest text that reads back as v: 1.000000000001 stays itself, not "1".
std::string shortest(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return {buf.data(), r.ptr};
}

} // namespace

std::int64_t reference_step_hz(Nanos update_period) {
  constexpr std::int64_t kNanosPerSecond = 1'000'000'000;
  return kNanosPerSecond / std::gcd(kNanosPerSecond, 2 * update_period.count());
}

bool reference_fits_update(double frequency_hz, Nanos update_period) {
  // A fraction of a hertz never fits: every multiple of a whole step is whole.
  if (!(frequency_hz >= 1.0 && frequency_hz <= static_cast<double>(kMaxReferenceHz)) ||
      std::floor(frequency_hz) != frequency_hz)
    return false;
  return static_cast<std::int64_t>(frequency_hz) % reference_step_hz(update_period) == 0;
}

std::optional<ParamsConflict> params_conflict(ModelVariant model, const Params& params) {
  const ModelTraits& m = traits(model);
  if (!reference_fits_update(params.excitation_hz, m.update_period)) {
    const std::int64_t step = reference_step_hz(m.update_period);
    std::string fitting;
    for (std::int64_t hz = step; hz <= kMaxReferenceHz; hz += step)
      fitting += (fitting.empty() ? "" : ", ") + std::to_string(hz);
    return ParamsConflict{{"excitation_hz", "model"},
                          "a reference whose half period 1/(2f) divides the " + std::string(m.name) + "'s " +
                              std::to_string(m.update_period.count() / 1000) +
                              " us update, so every update samples at a peak (models/pls2700/README.md "
                              "\"Decoder\", L377): a multiple of " +
                              std::to_string(step) + " Hz up to " + std::to_string(kMaxReferenceHz) + ": " +
                              fitting + " (got " + shortest(params.excitation_hz) + " Hz)"};
  }
  // A closed band [min, max]: one point (min == max) is a band; min > max holds no ratio, so
  // every signal would be a transducer fault (Err1) for good.
  if (params.min_stator_ratio > params.max_stator_ratio)
    return ParamsConflict{{"min_stator_ratio", "max_stator_ratio"},
                          "min_stator_ratio at most max_stator_ratio: the transducer-fault band "
                          "[min_stator_ratio, max_stator_ratio] is empty with " +
                              shortest(params.min_stator_ratio) + " > " + shortest(params.max_stator_ratio) +
                              ", a fault whatever the signal"};
  return std::nullopt;
}

} // namespace hilrig::models::pls2700
