#pragma once
// A scenario's host actions in a Scheduler's time: command writes with the AMCI
// Transmit/Acknowledge handshake (polled every host_poll) or raw, and status reads into
// observations, at their time or while the write above has Acknowledge set. The words go through HostWords:
// the virtual DUT's host interface in a virtual run, a Modbus link in a hardware run.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/scheduler.hpp"
#include "rig/campaign/campaign.hpp"
#include "rig/duts/dut.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::campaign {

// The board's host words: output (command) word k, input (status) word k.
class HostWords {
public:
  virtual ~HostWords() = default;
  virtual void write(std::size_t word, std::uint16_t value) = 0;
  [[nodiscard]] virtual std::uint16_t read(std::size_t word) = 0;
};

class HostSequence {
public:
  // Everything given outlives the sequence.
  HostSequence(Scheduler& scheduler, const Scenario& scenario, const duts::HostInterface& host,
               HostWords& words);
  HostSequence(const HostSequence&) = delete;
  HostSequence& operator=(const HostSequence&) = delete;

  // Schedules the first action; each next one starts at its time or when the one before it
  // has finished its handshake, whichever is later.
  void start();

  [[nodiscard]] std::vector<rig::Observation>& observations() { return observations_; }
  [[nodiscard]] std::vector<rig::Measurement>& handshakes() { return handshakes_; }

private:
  void step();
  void read(const HostAction& h);
  [[nodiscard]] bool ack();
  void poll_ack(bool want);
  void done();

  Scheduler& sched_;
  const Scenario& s_;
  duts::HostInterface host_;
  HostWords& words_;
  std::size_t next_ = 0;
  Nanos write_started_{0};
  std::vector<rig::Observation> observations_;
  std::vector<rig::Measurement> handshakes_;
};

} // namespace hilrig::campaign
