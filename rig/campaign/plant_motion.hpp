#pragma once
// A plant's trajectory as the rig's motion: constant-acceleration segments in encoder
// counts between the plant's knots (each integration step, breakpoint and located event),
// so the closed-form quadrature solver gives the encoder edges. Each segment passes exactly
// through both knots' positions (its acceleration is chosen so); a segment that ends in a
// standstill ends at speed 0 exactly. Between knots the quadratic differs from the
// integrated motion by at most |jerk| h^3 / 12 (0 for a constant torque).
//
// Closing the loop: an input (a board output) at time t rewinds the plant to its state at
// the last input, integrates it to t exactly, applies the input and plans again from t to
// the end. What lies before t is kept; the rig re-solves the encoder from t.

#include <memory>
#include <vector>

#include "models/plants/plant.hpp"
#include "rig/campaign/plant_spec.hpp"
#include "rig/checks/brake.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

[[nodiscard]] std::unique_ptr<plants::Plant> make_plant(const PlantSpec& spec);

class PlantMotion {
public:
  // Plans from the plant's start to `end`.
  PlantMotion(const PlantSpec& spec, double counts_per_turn, Nanos end);

  // The plan from the last input on (counts, counts/s): what the encoder plays now.
  [[nodiscard]] const signals::MotionProfile& plan() const { return plan_; }
  // An input changes at t (>= the last input's time): the plan is redone from t.
  void input(Nanos t, plants::PlantInput which, bool level);

  // The shaft's position at t in counts: the history before the last input, the plan from
  // it on (what a resolver's stators carry; the board samples at or before now).
  [[nodiscard]] double position(Nanos t) const;
  // The whole trajectory (committed history, then the plan), in counts.
  [[nodiscard]] signals::MotionProfile trajectory() const;
  // Its knots as the brake check reads the shaft: position changes up to the last one,
  // which is the plant's located standstill when the shaft came to rest.
  [[nodiscard]] std::vector<checks::PositionSample> samples() const;
  // Standstills the plant located, in time order (history and plan).
  [[nodiscard]] std::vector<Nanos> standstills() const;

private:
  // Integrates `plant` to `until`, appending a segment per knot.
  void integrate(plants::Plant& plant, Nanos until, std::vector<signals::Segment>& out) const;
  [[nodiscard]] signals::Segment segment(const plants::Knot& a, const plants::Knot& b) const;

  double per_rad_;
  Nanos end_;
  std::unique_ptr<plants::Plant> checkpoint_; // the plant at the last input
  std::vector<signals::Segment> history_;     // before the last input
  std::vector<Nanos> history_standstills_;
  signals::MotionProfile plan_;
  std::vector<Nanos> plan_standstills_;
};

} // namespace hilrig::campaign
