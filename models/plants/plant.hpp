#pragma once
// A plant: the machine around the board, integrated in virtual time. The rig asks it to
// advance, feeds it the board's outputs (valve, motor enable, step pulses) at the instant
// they change, and reads back the shaft the encoder sees as knots (time, angle, speed).
// Units are SI: rad, rad/s, N·m, kg·m², s. Every knot lies on the nanosecond grid; events
// (standstill, clutch lock or slip) are located to within one nanosecond.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/time.hpp"

namespace hilrig::plants {

// The board outputs (or rig lines) a plant can take.
enum class PlantInput : std::uint8_t {
  Valve,       // press clutch/brake valve: energized = clutch engaged and brake released
  MotorEnable, // motor torque on
  Step,        // stepper: a rising edge is one step in the direction of Direction
  Direction,   // stepper: high = forward
};

// The shaft the encoder sees at one instant.
struct Knot {
  Nanos time;
  double angle = 0.0; // rad
  double speed = 0.0; // rad/s
};

class Plant {
public:
  virtual ~Plant() = default;
  [[nodiscard]] virtual std::unique_ptr<Plant> clone() const = 0;

  // The knot at now().
  [[nodiscard]] virtual Knot state() const = 0;
  [[nodiscard]] Nanos now() const { return state().time; }
  // Integrates towards `until` (> now()): stops at the end of one integration step, at a
  // breakpoint (a parameter change, the brake's engagement or the end of its rise) or at a
  // located event, whichever comes first. Returns the knot reached.
  virtual Knot advance(Nanos until) = 0;
  // An input changes at now(). Inputs a plant does not take are ignored.
  virtual void input(PlantInput which, bool level) = 0;
  // Standstills located so far (the shaft came to rest and stayed), in time order.
  [[nodiscard]] virtual const std::vector<Nanos>& standstills() const = 0;
};

// A set of parameters taking effect at a time (a worn brake from t, added inertia).
template <class Params> struct ParamChange {
  Nanos at;
  Params params;
};

} // namespace hilrig::plants
