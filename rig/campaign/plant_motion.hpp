#pragma once
// A plant's trajectory as the rig's motion: constant-acceleration segments in encoder
// counts between the plant's knots (each integration step, breakpoint and located event),
// so the closed-form quadrature solver gives the encoder edges. Each segment passes exactly
// through both knots' positions (its acceleration is chosen so); a segment that ends in a
// standstill ends at speed 0 exactly. Between knots the quadratic differs from the
// integrated motion by at most |jerk| h^3 / 12 (0 for a constant torque).
//
// Closing the loop: an input (a board output) at time t rewinds the plant to its state at
// the last input, integrates it to t exactly, applies the input and plans again from t. What
// lies before t is kept; the rig re-solves the encoder from t. For a plant that resumes at
// its knots (Plant::resumes_at_knots, the stepper), the plan's knots up to t are the steps
// that integration takes (the same advance() calls from the same states in the same order):
// an input resumes from the plan's last knot at or before t, so only the partial step to t is
// integrated again. A plan reaches only a bounded
// horizon ahead (kPlanSteps integration steps); the rig extends it when the shaft gets
// there, so a run costs O(its length) however many inputs it takes (a stepper's every pulse
// is one), not a plan to the end per input.

#include <cstdint>
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
  // How an input finds the plant's state at its instant: from the plan's last knot at or before
  // it where the plant allows (the same state), or integrated from the last input (the
  // reference a test compares with).
  enum class Resume : std::uint8_t { AtKnot, FromInput };
  // Plans from the plant's start to `end`.
  PlantMotion(const PlantSpec& spec, double counts_per_turn, Nanos end, Resume resume = Resume::AtKnot);

  // The plan from the last input on (counts, counts/s): what the encoder plays now. It is
  // integrated as it is read (a stepper's next pulse usually replaces it a few steps in):
  // plan() holds its segments so far, grow() appends the next few knots' (false once it
  // reaches plan_end()). The segments are the same whenever they are integrated.
  [[nodiscard]] const signals::MotionProfile& plan() const { return plan_; }
  bool grow() const;
  // An input changes at t (>= the last input's time): the plan is redone from t.
  void input(Nanos t, plants::PlantInput which, bool level);
  // When the plan ends (the campaign's end, or its horizon).
  [[nodiscard]] Nanos plan_end() const { return horizon_; }
  // The shaft reached plan_end() (< the campaign's end): the plan so far becomes history and
  // the next one runs on from where it ended, the same steps it would have taken.
  void extend();

  // Integration steps a plan reaches ahead of its start.
  static constexpr std::int64_t kPlanSteps = 128;
  // Segments the history holds room for at the start: one per integration step to the end
  // and a fifth more (an input splits the step it falls in), at most this many (a plan
  // integrates the whole run, so the history reaches that length: reserved at once, it is not
  // copied to a twice larger block as it grows, and memory first touched costs system time).
  static constexpr std::size_t kHistoryReservedMax = std::size_t{1} << 22;
  // Knots grow() integrates at a time.
  static constexpr int kGrowKnots = 4;

  // The shaft's position at t in counts: the history before the last input, the plan from
  // it on (what a resolver's stators carry; the board samples at or before now).
  [[nodiscard]] double position(Nanos t) const;
  // Its speed at t in counts/s, from the same history and plan.
  [[nodiscard]] double velocity(Nanos t) const;
  // The whole trajectory (committed history, then the plan), in counts.
  [[nodiscard]] signals::MotionProfile trajectory() const;
  // The same, made in the history's own storage, once the run is over: after it, position(),
  // velocity(), samples() and trajectory() no longer see the history (standstills() does).
  [[nodiscard]] signals::MotionProfile take_trajectory();
  // Its knots as the brake check reads the shaft: position changes up to the last one,
  // which is the plant's located standstill when the shaft came to rest.
  [[nodiscard]] std::vector<checks::PositionSample> samples() const;
  // Standstills the plant located, in time order (history and plan).
  [[nodiscard]] std::vector<Nanos> standstills() const;

private:
  [[nodiscard]] const signals::Segment* history_at(Nanos t) const;
  // Integrates `plant` to `until`, appending a segment per knot.
  void integrate(plants::Plant& plant, Nanos until, std::vector<signals::Segment>& out) const;
  [[nodiscard]] signals::Segment segment(const plants::Knot& a, const plants::Knot& b) const;
  // The plan from live_'s state (which becomes the checkpoint) to the horizon, starting at
  // `start` counts.
  void plan_from(double start);
  // The plan's knot an input at t resumes from: the last one at or before t that integration
  // towards t reaches too (not one the horizon cut short before t).
  [[nodiscard]] std::size_t resume_knot(Nanos t) const;
  // Grows the plan until it holds t (a segment ending after t) or reaches its horizon.
  void plan_through(Nanos t) const;
  void plan_all() const { plan_through(Nanos::max()); }

  double per_rad_;
  Nanos end_;
  Nanos ahead_;                               // a plan's horizon
  bool keep_knots_;                           // inputs resume at the plan's knots (kept in knots_)
  std::unique_ptr<plants::Plant> checkpoint_; // the plant at the plan's start
  std::vector<signals::Segment> history_;     // before the last input
  std::vector<Nanos> history_standstills_;
  Nanos horizon_; // where the plan ends
  // The plan as integrated so far (logically const: a function of the checkpoint).
  mutable std::unique_ptr<plants::Plant> live_; // the plant where the plan's segments end
  // The plan's knots so far, the first its start (only that one unless keep_knots_).
  mutable std::vector<plants::Knot> knots_;
  mutable std::size_t live_known_ = 0; // live_'s standstills already in plan_standstills_
  mutable signals::MotionProfile plan_;
  mutable std::vector<Nanos> plan_standstills_;
};

} // namespace hilrig::campaign
