#include "models/smd23e/params.hpp"

#include <array>
#include <utility>

namespace hilrig::models::smd23e {

namespace {
struct FaultName {
  Fault fault;
  std::string_view name;
  std::string_view description;
};
constexpr std::array<FaultName, 5> kNames{{
    {Fault::None, "none", "as specified"},
    {Fault::WrongAcceleration, "wrong-acceleration",
     "ramps run at wrong_accel_factor (0.5) x the programmed acceleration and deceleration"},
    {Fault::LostSteps, "lost-steps",
     "the shaft misses one step in every lost_step_interval (100) issued; the position register does not "
     "know"},
    {Fault::IgnoredLimit, "ignored-limit",
     "the CW/CCW limit inputs have no effect (moves and homing drive on)"},
    {Fault::LateStop, "late-stop",
     "stops from the limit, E-Stop and Stop Jog inputs and from Hold/Immediate Stop act late_stop_delay (20 "
     "ms) late"},
}};
} // namespace

std::string_view fault_name(Fault f) {
  for (const auto& n : kNames) {
    if (n.fault == f) {
      return n.name;
    }
  }
  return "none";
}

std::string_view fault_description(Fault f) {
  for (const auto& n : kNames) {
    if (n.fault == f) {
      return n.description;
    }
  }
  return "as specified";
}

std::optional<Fault> fault_from_name(std::string_view name) {
  for (const auto& n : kNames) {
    if (n.name == name) {
      return n.fault;
    }
  }
  return std::nullopt;
}

std::vector<std::string_view> fault_names() {
  std::vector<std::string_view> out;
  for (const auto& n : kNames) {
    if (n.fault != Fault::None) {
      out.push_back(n.name);
    }
  }
  return out;
}

} // namespace hilrig::models::smd23e
