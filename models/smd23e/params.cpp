#include "models/smd23e/params.hpp"

#include <array>
#include <utility>

namespace hilrig::models::smd23e {

namespace {
constexpr std::array<std::pair<Fault, std::string_view>, 5> kNames{{
    {Fault::None, "none"},
    {Fault::WrongAcceleration, "wrong-acceleration"},
    {Fault::LostSteps, "lost-steps"},
    {Fault::IgnoredLimit, "ignored-limit"},
    {Fault::LateStop, "late-stop"},
}};
} // namespace

std::string_view fault_name(Fault f) {
  for (const auto& [fault, name] : kNames) {
    if (fault == f) {
      return name;
    }
  }
  return "none";
}

std::optional<Fault> fault_from_name(std::string_view name) {
  for (const auto& [fault, n] : kNames) {
    if (n == name) {
      return fault;
    }
  }
  return std::nullopt;
}

std::vector<std::string_view> fault_names() {
  std::vector<std::string_view> out;
  for (const auto& [fault, name] : kNames) {
    if (fault != Fault::None) {
      out.push_back(name);
    }
  }
  return out;
}

} // namespace hilrig::models::smd23e
