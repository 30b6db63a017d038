#pragma once
// Wires an SsiSlave to two lines in scheduled time: it listens to the master's clock line
// and drives the data line, each data edge at its own time and the monoflop expiry as a
// scheduled event. Works with any backend that gives a LineInput, a LineOutput and a
// Scheduler whose now() is the lines' time (the virtual bus).

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "signals/ssi_slave.hpp"

namespace hilrig::signals {

class SsiSlaveNode {
public:
  // Subscribes to `clock`; drives `data` high (idle) at once. The slave, lines and
  // scheduler must outlive the node.
  SsiSlaveNode(Scheduler& scheduler, SsiSlave& slave, LineInput& clock, LineOutput& data);
  SsiSlaveNode(const SsiSlaveNode&) = delete;
  SsiSlaveNode& operator=(const SsiSlaveNode&) = delete;

  // Applies faults now (a stuck line changes level at once).
  void set_faults(const SsiSlaveFaults& faults);

private:
  void on_clock(const Edge& edge);
  void drive(const Edge& edge);
  void arm_expiry();

  Scheduler& scheduler_;
  SsiSlave& slave_;
  LineOutput& data_;
  EventId expiry_{};
};

} // namespace hilrig::signals
