#pragma once
// A test harness for the hardware run: the rig's ports (core/rt_ports.hpp) looped through a
// virtual DUT. Each edge the RT loop writes reaches the DUT's pin `delay` after the time it
// was scheduled for (the harness's wire), and the DUT's output edges come back stamped on the
// run's clock. The DUT runs in virtual time, advanced as real time passes but never up to an
// edge not yet written, so what it sees does not depend on when the loop woke: the capture
// is deterministic. (Test code: it allocates inside poll(), which a real port may not.)

#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/duts/dut.hpp"
#include "rig/hardware/drive_plan.hpp"
#include "rig/hardware/rig_ports.hpp"

namespace hilrig::hardware::test {

inline Nanos monotonic_now() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

class VirtualDutPorts final : public RigPorts {
public:
  VirtualDutPorts(const campaign::Scenario& s, const DrivePlan& plan, std::vector<ScheduledEdge> schedule,
                  Nanos delay, std::uint64_t seed)
      : bus_(sched_), schedule_(std::move(schedule)), delay_(delay), end_(s.end), out_(*this), in_(*this) {
    for (const PlannedLine& p : plan.outputs) drivers_.push_back(&bus_.line(p.rig, p.initial).driver());
    for (std::size_t i = 0; i < plan.inputs.size(); ++i)
      bus_.line(plan.inputs[i].rig).reader().on_edge([this, i](const Edge& e) {
        pending_.push_back(InputEdge{start_ + e.time, static_cast<std::uint16_t>(i), e.level});
      });
    const duts::DutInfo* info = duts::find_dut(s.dut.model);
    std::map<std::string, duts::ParamValue, std::less<>> given;
    for (const auto& [name, p] : s.dut.params) given[name] = p.value;
    dut_ = info->make(sched_, info->with_defaults(given), s.dut.variant, seed);
    std::map<std::string, std::string, std::less<>> pins;
    for (const campaign::Wire& w : s.wiring) pins[w.board] = w.rig;
    dut_->attach(bus_, pins);
  }

  RtOutputPort& outputs() override { return out_; }
  RtInputPort* inputs() override { return &in_; }
  campaign::HostWords* host() override { return host_; }
  ResolverCan* resolver() override { return can_; }
  void begin(Nanos start) override { start_ = start; }

  void set_host(campaign::HostWords* host) { host_ = host; }
  void set_resolver(ResolverCan* can) { can_ = can; }
  // Writes that were not the next edge of the schedule (line or level).
  [[nodiscard]] std::size_t mismatches() const { return mismatches_; }
  [[nodiscard]] std::size_t written() const { return written_; }

private:
  struct Out final : RtOutputPort {
    explicit Out(VirtualDutPorts& harness) : h(harness) {}
    void write(std::uint16_t line, Level level) noexcept override { h.write(line, level); }
    VirtualDutPorts& h;
  };
  struct In final : RtInputPort {
    explicit In(VirtualDutPorts& harness) : h(harness) {}
    std::size_t poll(std::span<InputEdge> out) noexcept override { return h.poll(out); }
    VirtualDutPorts& h;
  };

  void write(std::uint16_t line, Level level) {
    if (written_ >= schedule_.size() || line >= drivers_.size()) {
      ++mismatches_;
      return;
    }
    const ScheduledEdge& e = schedule_[written_++];
    if (e.line != line || e.level != level) ++mismatches_;
    LineOutput* out = drivers_[line];
    sched_.at(std::max(sched_.now(), e.time + delay_), [out, level] { out->set(level); });
  }

  std::size_t poll(std::span<InputEdge> out) {
    Nanos limit = std::min(monotonic_now() - start_, end_);
    if (written_ < schedule_.size()) limit = std::min(limit, schedule_[written_].time + delay_ - Nanos{1});
    if (limit > sched_.now()) sched_.run_until(limit);
    std::size_t n = 0;
    while (n < out.size() && next_ < pending_.size()) out[n++] = pending_[next_++];
    return n;
  }

  Scheduler sched_;
  virt::VirtualBus bus_;
  std::vector<ScheduledEdge> schedule_;
  Nanos delay_;
  Nanos end_;
  Out out_;
  In in_;
  std::unique_ptr<duts::Dut> dut_;
  std::vector<LineOutput*> drivers_;
  std::vector<InputEdge> pending_;
  std::size_t next_ = 0;
  std::size_t written_ = 0;
  std::size_t mismatches_ = 0;
  Nanos start_{0};
  campaign::HostWords* host_ = nullptr;
  ResolverCan* can_ = nullptr;
};

} // namespace hilrig::hardware::test
