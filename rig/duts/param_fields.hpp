#pragma once
// A model's [MODEL] choices as one table of fields: each row names a member of the model's
// Params struct, so `hilrig list` (ParamInfo: kind, default, meaning, range), the campaign's
// dut.params, `hilrig serve --param` and the model's construction all read the same row. A
// new choice is one row.

#include <cstdint>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "rig/duts/dut.hpp"

namespace hilrig::duts {

template <typename P> using ParamMember = std::variant<std::int64_t P::*, double P::*, Nanos P::*, bool P::*>;

template <typename P> struct ParamField {
  const char* name;
  ParamMember<P> member;
  const char* description;
  ParamRange range = {}; // between(...), with the manual line or rig limit behind it; booleans: {}
};

template <typename P>
[[nodiscard]] std::vector<ParamInfo> param_infos(std::span<const ParamField<P>> fields) {
  const P defaults{};
  std::vector<ParamInfo> out;
  for (const ParamField<P>& f : fields) {
    ParamInfo info;
    info.name = f.name;
    info.description = f.description;
    info.range = f.range;
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(defaults.*member)>;
          info.default_value = defaults.*member;
          if constexpr (std::is_same_v<T, std::int64_t>) info.kind = ParamKind::Integer;
          if constexpr (std::is_same_v<T, double>) info.kind = ParamKind::Number;
          if constexpr (std::is_same_v<T, Nanos>) info.kind = ParamKind::Duration;
          if constexpr (std::is_same_v<T, bool>) info.kind = ParamKind::Boolean;
        },
        f.member);
    out.push_back(std::move(info));
  }
  return out;
}

// The model's Params from a DUT's values (each already of its field's kind and in range).
template <typename P>
[[nodiscard]] P params_from(std::span<const ParamField<P>> fields, const DutParams& values) {
  P p{};
  for (const ParamField<P>& f : fields) {
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(p.*member)>;
          if constexpr (std::is_same_v<T, std::int64_t>) p.*member = values.integer(f.name);
          if constexpr (std::is_same_v<T, double>) p.*member = values.number(f.name);
          if constexpr (std::is_same_v<T, Nanos>) p.*member = values.duration(f.name);
          if constexpr (std::is_same_v<T, bool>) p.*member = values.boolean(f.name);
        },
        f.member);
  }
  return p;
}

} // namespace hilrig::duts
