#pragma once
// The rig's drive of the lines it owns, in a Scheduler's time: the encoder edges solved
// from the motion (with missing-edge faults), the discrete stimuli, signal faults, a probe
// pulse and the press brake. The virtual run drives bus lines with it; the hardware run
// drives recording outputs with it to precompute the RT loop's edge schedule, so both
// backends play the same edges. A line another source synthesizes (the [ssi] transducer's
// DATA, a plant's encoder or valve monitor) is driven through it too (source()), so a signal
// fault overrides that source as it does the drive's own encoder.

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/campaign/motion.hpp"
#include "rig/checks/brake.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::campaign {

class ShaftTrace; // rig/campaign/run_trace.hpp

// The campaign's encoder over a profile already in counts (units_per_turn = counts per
// turn), count = floor(position): what the rig plays, from a motion or a plant.
[[nodiscard]] signals::QuadratureEncoder rig_encoder(const EncoderSpec& spec);

// Its encoder edges are the scheduler's EventStream: one ordinary event per edge, ordered as
// a scheduled event would be, without a heap entry each.
class RigDrive final : private EventStream {
public:
  // The scheduler, scenario and motion outlive the drive.
  RigDrive(Scheduler& scheduler, const Scenario& scenario, const BuiltMotion& motion);
  RigDrive(const RigDrive&) = delete;
  RigDrive& operator=(const RigDrive&) = delete;

  // The level a rig line starts at: the encoder's from the start count, a brake line's
  // released level, otherwise low.
  [[nodiscard]] Level initial_level(std::string_view rig) const;
  // Hands the drive one line it owns (a board input), at the level it starts at
  // (initial_level(rig), or its source's).
  void own(const std::string& rig, LineOutput& out);
  // What another source drives an owned line through: its levels are the line's unless a
  // signal fault overrides them (a stuck level holds, a glitch inverts, a missing edge of
  // enc.A/enc.B is lost). The drive's own encoder then leaves the line to the source. Lives
  // as long as the drive; throws std::logic_error for a line not owned.
  [[nodiscard]] LineOutput& source(const std::string& rig);
  // Schedules everything up to the scenario's end. Throws RigFault for a stimulus on a
  // line the rig does not own.
  void start(const std::vector<Stimulus>& faults, const std::optional<Stimulus>& probe, bool record_motion);

  // Each edge as an ordinary heap event (Scheduler::at), not the stream: the oracle's engine
  // (--exact-scan), so the differential test compares the stream with it. Before start().
  void edges_as_heap_events() { heap_edges_ = true; }

  [[nodiscard]] std::int64_t count() const { return count_; }
  // Every count change from now on also goes to `shaft` (the run's trace).
  void trace_shaft(ShaftTrace* shaft) { shaft_ = shaft; }
  // Every count change so far (when recorded), from the start sample at time 0.
  [[nodiscard]] std::vector<checks::PositionSample>& motion() { return motion_; }

private:
  // A line the rig drives: the level the stimulus (or source) wants, and faults that
  // override it.
  struct DrivenLine {
    LineOutput* out = nullptr;
    Level intended = Level::Low;
    int forced = 0;       // stuck faults in force: the line holds the last one's level
    int inverted = 0;     // glitches in force: the line is the opposite of `intended`
    bool sourced = false; // another source drives it (source())
    void want(Level l) {
      intended = l;
      show();
    }
    // The line as the faults in force leave it (a stuck fault sets its own level).
    void show() {
      if (forced == 0) out->set(inverted > 0 ? !intended : intended);
    }
  };
  // The LineOutput a source drives through: each change of its level is an edge, lost to a
  // missing_edges fault in force or wanted of the line.
  struct Source final : LineOutput {
    Source(RigDrive& drive, std::string rig, DrivenLine& line)
        : drive_(drive), rig_(std::move(rig)), line_(line), level_(line.intended) {}
    void set(Level level) override;
    [[nodiscard]] Level driven() const override { return level_; }
    RigDrive& drive_;
    std::string rig_;
    DrivenLine& line_;
    Level level_;
  };
  struct MissingEdges {
    Stimulus fault;
    std::int64_t seen;
  };
  // A bounce's edges (edge k at `at + k * period`, the level `level` on even k), each scheduled
  // by the one before in the place it took when all were scheduled at start: one pending event
  // a train, not thousands in the heap (a die-protection train of 17,747 edges).
  struct BounceTrain {
    Scheduler* sched;
    DrivenLine* line;
    Level level;
    Nanos at, period;
    std::int64_t edges; // 2 * bounces + 1
    Reservation first;
    std::int64_t next = 0;
    void schedule_next();
  };

  DrivenLine* find(std::string_view rig);
  // The encoder line the drive's own solver plays (nullptr: not owned, or sourced).
  DrivenLine* own_encoder(std::string_view rig);
  // Whether an edge of `rig` at `t` is lost to a missing_edges fault in force (each fault
  // counts the edges in its span and loses every n-th).
  bool lost(std::string_view rig, Nanos t);
  void fire() override { encoder_edge(); }
  void encoder_edge();
  // Schedules next_edge_ (when there is one by the end).
  void schedule_edge();
  // The next A/B edge from the solver, or nothing when the motion has no more.
  [[nodiscard]] std::optional<signals::QuadEdge> pull_edge();
  void schedule(const Stimulus& st);

  Scheduler& sched_;
  const Scenario& s_;
  const BuiltMotion& built_;
  // The encoder in counts, count = floor(position) (positions in checks name the count
  // they enter): the one quadrature solver every stimulus path uses.
  signals::QuadratureEdgeSolver edges_;
  std::array<signals::QuadEdge, 64> edge_buffer_{};
  std::size_t edge_next_ = 0, edge_filled_ = 0;
  std::map<std::string, Level, std::less<>> brake_level_;
  std::map<std::string, DrivenLine, std::less<>> driven_;
  std::deque<Source> sources_; // stable addresses: the sources hold them
  DrivenLine* enc_a_ = nullptr;
  DrivenLine* enc_b_ = nullptr;
  std::optional<signals::QuadEdge> next_edge_;
  std::vector<MissingEdges> missing_;
  std::deque<BounceTrain> trains_; // stable addresses: their events hold them
  std::int64_t count_ = 0;
  ShaftTrace* shaft_ = nullptr;
  bool record_motion_ = true;
  bool heap_edges_ = false;
  std::vector<checks::PositionSample> motion_;
};

} // namespace hilrig::campaign
