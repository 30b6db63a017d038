#include "rig/hardware/edge_schedule.hpp"

#include <memory>

#include "core/scheduler.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/rig_drive.hpp"

namespace hilrig::hardware {

namespace {

// An output the drive sets: each level change becomes a scheduled edge at the scheduler's now.
class RecordingLine final : public LineOutput {
public:
  RecordingLine(const Scheduler& sched, std::vector<ScheduledEdge>& edges, std::uint16_t index, Level initial)
      : sched_(sched), edges_(edges), index_(index), level_(initial) {}
  void set(Level level) override {
    if (level == level_) return; // as on a wire: the level it has is not an edge
    level_ = level;
    edges_.push_back(ScheduledEdge{sched_.now(), index_, level});
  }
  [[nodiscard]] Level driven() const override { return level_; }

private:
  const Scheduler& sched_;
  std::vector<ScheduledEdge>& edges_;
  std::uint16_t index_;
  Level level_;
};

} // namespace

EdgeSchedule build_schedule(const campaign::RunInputs& in, const DrivePlan& plan) {
  const campaign::Scenario& s = *in.scenario;
  if (s.plant)
    throw campaign::RigFault("a [plant] closes the loop through the board's outputs, which the precomputed "
                             "schedule of a rig run cannot: plant campaigns run on the virtual backend");
  if (!s.ssi.data_line.empty())
    throw campaign::RigFault(
        "an [ssi] transducer answers the board's clock as it comes, which the precomputed "
        "schedule of a rig run cannot: [ssi] campaigns run on the virtual backend");
  EdgeSchedule out;
  out.motion = campaign::build_motion("", s.motion, s.encoder);
  Scheduler sched;
  campaign::RigDrive drive(sched, s, out.motion);
  std::vector<std::unique_ptr<RecordingLine>> lines;
  for (std::size_t i = 0; i < plan.outputs.size(); ++i) {
    const PlannedLine& p = plan.outputs[i];
    lines.push_back(std::make_unique<RecordingLine>(sched, out.edges, static_cast<std::uint16_t>(i),
                                                    drive.initial_level(p.rig)));
    drive.own(p.rig, *lines.back());
  }
  drive.start(in.faults, in.probe, in.record_motion);
  sched.run_until(s.end);
  out.positions = std::move(drive.motion());
  checks::append_motion(out.positions, {s.end, static_cast<double>(drive.count())});
  return out;
}

} // namespace hilrig::hardware
