#pragma once
// Params each in range that do not go together, refused before the module runs (README
// "Parameters"): a reference whose peaks miss the update grid, an empty transducer-fault band.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/time.hpp"
#include "models/pls2700/model_variant.hpp"
#include "models/pls2700/params.hpp"

namespace hilrig::models::pls2700 {

// The highest reference offered (10 kHz: the common resolver references run up to it).
inline constexpr std::int64_t kMaxReferenceHz = 10'000;

// The update clock is locked to the reference (README "Decoder"): every update samples at a
// peak only when the half period 1/(2f) divides the update period P, i.e. 2 f P is whole. So
// f is a multiple of this step, 1e9 / gcd(1e9, 2 P_ns) Hz: 2,500 Hz for 200 us, 1,250 Hz for
// 400 us (L377). Exact: whole hertz and nanoseconds, no float rounding.
[[nodiscard]] std::int64_t reference_step_hz(Nanos update_period);
[[nodiscard]] bool reference_fits_update(double frequency_hz, Nanos update_period);

struct ParamsConflict {
  // The settings in conflict, the one to blame first: Params fields, or "model", as named in
  // a campaign's dut.params (README "Parameters").
  std::vector<std::string_view> fields;
  std::string expected; // what they must be, with the values that are
};

// The first rule `params` break on `model`, or nullopt.
[[nodiscard]] std::optional<ParamsConflict> params_conflict(ModelVariant model, const Params& params);

} // namespace hilrig::models::pls2700
