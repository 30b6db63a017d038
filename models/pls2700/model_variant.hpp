#pragma once
// The seven Series 2700 modules (pls2700.md §1 table) and what sets them apart: channels,
// Scale Factor ceiling, which outputs have advances, the OFF <= ON advance rule, the
// 2742-18 inputs, BTR length and the position/output update period (L377, L457).
#include <array>
#include <optional>
#include <string_view>

#include "core/time.hpp"

namespace hilrig::models::pls2700 {

enum class ModelVariant : std::uint8_t { M2731, M2731_04, M2732, M2732_04, M2741, M2742, M2742_18 };

struct ModelTraits {
  ModelVariant variant;
  std::string_view name; // as the manual writes it: "2731-04"
  int channels;          // resolver channels, 1 or 2
  int max_scale_factor;  // 1024 (273x) or 4096 (274x)
  int advance_outputs;   // outputs 1..n have ON/OFF advances (5 or 8)
  bool off_le_on_rule;   // a_off <= a_on enforced (not on -04, L431, L437)
  bool has_inputs;       // 2742-18 discrete inputs and cycle logic (Appendix A)
  bool single_transfer;  // 2731-04 publishes position as a single-transfer word (L433)
  int btr_words;         // 3 (1-ch) or 5 (2-ch) (L1260)
  Nanos update_period;   // 200 us (1-ch) or 400 us (2-ch) (L377, L457)
};

inline constexpr std::array<ModelTraits, 7> kModels{{
    {ModelVariant::M2731, "2731", 1, 1024, 5, true, false, false, 3, Nanos{200'000}},
    {ModelVariant::M2731_04, "2731-04", 1, 1024, 5, false, false, true, 3, Nanos{200'000}},
    {ModelVariant::M2732, "2732", 2, 1024, 8, true, false, false, 5, Nanos{400'000}},
    {ModelVariant::M2732_04, "2732-04", 2, 1024, 8, false, false, false, 5, Nanos{400'000}},
    {ModelVariant::M2741, "2741", 1, 4096, 5, true, false, false, 3, Nanos{200'000}},
    {ModelVariant::M2742, "2742", 2, 4096, 8, true, false, false, 5, Nanos{400'000}},
    // 2742-18: advances and the OFF <= ON rule inherited from the 2742 [I, digest §1].
    {ModelVariant::M2742_18, "2742-18", 2, 4096, 8, true, true, false, 5, Nanos{400'000}},
}};

[[nodiscard]] const ModelTraits& traits(ModelVariant variant);
[[nodiscard]] std::optional<ModelVariant> model_from_name(std::string_view name);

} // namespace hilrig::models::pls2700
