#include "signals/ssi_slave_node.hpp"

namespace hilrig::signals {

SsiSlaveNode::SsiSlaveNode(Scheduler& scheduler, SsiSlave& slave, LineInput& clock, LineOutput& data)
    : scheduler_(scheduler), slave_(slave), data_(data) {
  data_.set(slave_.data());
  clock.on_edge([this](const Edge& e) { on_clock(e); });
}

void SsiSlaveNode::set_faults(const SsiSlaveFaults& faults) {
  if (auto e = slave_.set_faults(faults, scheduler_.now())) data_.set(e->level);
}

void SsiSlaveNode::drive(const Edge& edge) {
  if (edge.time <= scheduler_.now()) {
    data_.set(edge.level);
    return;
  }
  scheduler_.at(edge.time, [this, level = edge.level] { data_.set(level); });
}

void SsiSlaveNode::on_clock(const Edge& edge) {
  const SsiDataEdges out = slave_.on_clock(edge); // keep it alive for the loop
  for (const Edge& d : out.view()) drive(d);
  arm_expiry();
}

void SsiSlaveNode::arm_expiry() {
  // Every clock edge retriggers the monoflop: move the one pending expiry event.
  if (expiry_.valid()) scheduler_.cancel(expiry_);
  expiry_ = EventId{};
  const Nanos deadline = slave_.deadline();
  if (deadline == Nanos::max()) return;
  expiry_ = scheduler_.at(deadline, [this] {
    expiry_ = EventId{};
    if (auto e = slave_.advance_to(scheduler_.now())) data_.set(e->level);
  });
}

} // namespace hilrig::signals
