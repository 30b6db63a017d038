#pragma once
// A virtual digital line: one driver, many readers. A level set by the driver at time t
// reaches readers at t + propagation delay (0 by default), as an Edge with that time.
// With no delay readers see the edge inside set(); with a delay it is a scheduled event.
// The delay is a transport delay: a pulse shorter than it still arrives whole. Each edge is
// recorded in the trace (if any) under the line's name when readers see it, and the initial
// level as the signal's initial value. While the line powers up (set_powering_up), a level
// driven is where it starts, not an edge. The line must outlive the scheduler's pending events.

#include <memory>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "core/trace.hpp"

namespace hilrig::virt {

class DigitalLine {
public:
  DigitalLine(Scheduler& scheduler, std::string name, Level initial, TraceRecorder* trace);
  ~DigitalLine();
  DigitalLine(const DigitalLine&) = delete;
  DigitalLine& operator=(const DigitalLine&) = delete;

  [[nodiscard]] const std::string& name() const { return name_; }
  // Applies to levels set from now on; a negative delay throws std::invalid_argument.
  void set_propagation_delay(Nanos delay);
  [[nodiscard]] Nanos propagation_delay() const;
  // While powering up, a level driven is the line's initial level: readers' level() and the
  // trace's initial value, with no edge and no handler called. A board drives its outputs'
  // idle levels as it powers up; where the line starts is no edge at time 0, whatever the
  // level (a capture's first sample of a line is its level too). Off by default.
  void set_powering_up(bool on);

  // The one driving end. Setting the level it already has is not an edge.
  [[nodiscard]] LineOutput& driver();
  // A new reading end; each reader keeps its own handlers.
  [[nodiscard]] LineInput& reader();

  [[nodiscard]] Level level() const; // as readers see it now
  [[nodiscard]] std::uint64_t edge_count() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_; // stable address: scheduled deliveries point at it
  std::string name_;
};

} // namespace hilrig::virt
