#include "models/pls2700/model_variant.hpp"

namespace hilrig::models::pls2700 {

const ModelTraits& traits(ModelVariant variant) { return kModels[static_cast<std::size_t>(variant)]; }

std::optional<ModelVariant> model_from_name(std::string_view name) {
  for (const ModelTraits& t : kModels) {
    if (t.name == name) {
      return t.variant;
    }
  }
  return std::nullopt;
}

} // namespace hilrig::models::pls2700
