#pragma once
// A plant: the machine around the board, integrated in virtual time. The rig asks it to
// advance, feeds it the board's outputs (valve, motor enable, step pulses) at the instant
// they change, and reads back the shaft the encoder sees as knots (time, angle, speed).
// Units are SI: rad, rad/s, N·m, kg·m², s. Every knot lies on the nanosecond grid; events
// (standstill, clutch lock or slip) are located to within one nanosecond.

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
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
  // Becomes a copy of `other`, a plant of this one's own kind, reusing its storage.
  virtual void assign(const Plant& other) = 0;
  // Whether the plant resumes at its knots: (1) `until` only cuts a step short: advance(until)
  // reaches min(until, e), where e (the end of the integration step, a breakpoint or a
  // parameter change) does not depend on until, and nothing is located inside a step (a
  // shorter step could place an event elsewhere); so a knot reached integrating towards a
  // later instant is, when it lies before that instant (or at `until` itself), the knot
  // integrating towards `until` reaches from the same state. (2) Its state after a step is
  // its knot and what resume_at() restores from it.
  [[nodiscard]] virtual bool resumes_at_knots() const { return false; }
  // For a plant that resumes at its knots: puts this plant, at a knot of an integration (a
  // sequence of advance() calls with no input between), at `later`, a knot that integration
  // reached afterwards, in the state it had there.
  virtual void resume_at(const Knot& later) {
    (void)later;
    throw std::logic_error("this plant does not resume at its knots");
  }

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
