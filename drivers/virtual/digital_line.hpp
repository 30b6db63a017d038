#pragma once
// A virtual digital line: one driver, many readers. A level set by the driver at time t
// reaches readers at t + propagation delay (0 by default), as an Edge with that time.

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

  [[nodiscard]] const std::string& name() const { return name_; }
  void set_propagation_delay(Nanos delay) { delay_ = delay; }

  // The one driving end. Setting the level it already has is not an edge.
  [[nodiscard]] LineOutput& driver();
  // A new reading end; each reader keeps its own handlers.
  [[nodiscard]] LineInput& reader();

  [[nodiscard]] Level level() const;        // as readers see it now
  [[nodiscard]] std::uint64_t edge_count() const;

  // (private state: implementer's choice)
private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
  std::string name_;
  Nanos delay_{0};
};

} // namespace hilrig::virt
