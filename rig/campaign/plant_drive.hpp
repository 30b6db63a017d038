#pragma once
// The rig's drive of a plant scenario, in a Scheduler's time: the encoder lines played
// from the plant's motion (the closed-form quadrature solver over PlantMotion's plan), the
// board outputs wired to plant inputs acting on it the instant they change, the rig's own
// plant commands, and the valve monitor line. Virtual backend only: on a rig the loop
// would have to close in real time.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/campaign/plant_motion.hpp"
#include "rig/results/motion_record.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::campaign {

class ShaftTrace; // rig/campaign/run_trace.hpp

class PlantDrive {
public:
  // The scheduler and scenario (which has a plant) outlive the drive.
  PlantDrive(Scheduler& scheduler, const Scenario& scenario);
  PlantDrive(const PlantDrive&) = delete;
  PlantDrive& operator=(const PlantDrive&) = delete;

  // Whether the drive owns a rig line (the encoder's, the valve monitor) or watches one (a
  // board output acting on the plant).
  [[nodiscard]] bool drives(std::string_view rig) const;
  [[nodiscard]] bool watches(std::string_view rig) const;
  [[nodiscard]] Level initial_level(std::string_view rig) const;
  void own(const std::string& rig, LineOutput& out);
  void watch(const std::string& rig, LineInput& in);
  // Schedules the encoder and the commands.
  void start();
  // Every count change from now on also goes to `shaft` (the run's trace).
  void trace_shaft(ShaftTrace* shaft) { shaft_ = shaft; }
  [[nodiscard]] std::int64_t count() const { return count_; }

  [[nodiscard]] const PlantMotion& motion() const { return motion_; }
  // The run is over: the shaft's whole trajectory (PlantMotion::take_trajectory).
  [[nodiscard]] signals::MotionProfile take_trajectory() { return motion_.take_trajectory(); }
  // The board outputs (and rig commands) that acted on the plant, as they changed, and the
  // standstills it located: the events of the report's speed/position plot.
  [[nodiscard]] std::vector<rig::MotionEvent> events() const;
  // The encoder count's changes as played (checks::append_motion-compacted): what the board
  // counted, whose last change a board timing a stop sees as its end.
  [[nodiscard]] const std::vector<checks::PositionSample>& counts() const { return counts_; }

private:
  void apply(plants::PlantInput which, bool level);
  void resolve(); // the solver over the new plan, from now
  // Schedules the plan's extension at its horizon (at the place resolve() took for it) once the
  // drive's next event is `next` (Nanos::max(): none) and that is no earlier than the horizon.
  void extend_by(Nanos next);
  // The next edge's event, at the place it takes in the order of events at its time.
  void schedule_next();
  // Looks for that edge in the plan integrated a few knots further; when none is there yet,
  // looks again (at the same place) where the plan ends: the plan is integrated only a little
  // ahead of the shaft, since the next input (a stepper's next pulse) usually replaces it.
  void seek();
  void play();

  Scheduler& sched_;
  const Scenario& s_;
  const PlantSpec& spec_;
  PlantMotion motion_;
  signals::QuadratureEncoder encoder_;
  // Over motion_.plan(), restarted at each new plan.
  signals::QuadratureEdgeSolver solver_;
  // One edge (and its Z edge) at a time: the solver integrates the plan only as far as the
  // next edge, and the next input usually replaces the plan before the edge after.
  std::array<signals::QuadEdge, 2> buffer_{};
  std::size_t next_ = 0, filled_ = 0;
  std::uint64_t generation_ = 0; // edges scheduled under an older plan are dropped
  Reservation next_place_;       // where the next edge's event stands among those at its time
  EventId next_event_{};         // the next edge's (or look's) event
  // The plan's extension at its horizon: where its event stands (taken when the plan began, as
  // scheduling it then would), whether it is still to be scheduled, and the event. It is
  // scheduled only when the drive itself would not act again before the horizon: a stepper's
  // next pulse usually replaces the plan long before.
  Reservation extend_place_;
  bool extend_owed_ = false;
  EventId extend_event_{};
  int grows_left_ = 0; // PlantMotion::grow() calls this look at the plan may make
  // grow() calls a look at the plan makes before waiting for the shaft to get there: for a
  // stepper kGrowsPerLook (its next pulse usually replaces the plan a few knots in); no limit
  // for a plant whose inputs are rare (a press, a rotary axis), whose plan the shaft mostly
  // plays to its end: one look finds the next edge (or integrates the plan whole) rather than
  // a look every few knots.
  static constexpr int kGrowsPerLook = 1;
  int grows_per_look_;
  std::int64_t count_ = 0;
  ShaftTrace* shaft_ = nullptr;
  std::vector<checks::PositionSample> counts_;
  LineOutput* enc_a_ = nullptr;
  LineOutput* enc_b_ = nullptr;
  LineOutput* monitor_ = nullptr;
  std::vector<std::pair<plants::PlantInput, LineInput*>> watched_;
  bool valve_ = true;
  std::vector<rig::MotionEvent> events_;
  std::array<std::optional<bool>, 4> last_level_{}; // per PlantInput: the level last recorded
};

} // namespace hilrig::campaign
