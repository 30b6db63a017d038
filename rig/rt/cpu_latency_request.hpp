#pragma once
// Keeps the CPUs out of deep idle states while a run lasts, as cyclictest does: the PM QoS
// interface takes a latency bound written to /dev/cpu_dma_latency and holds it for as long
// as the file stays open. Without it, waking from a C-state adds tens of microseconds.

#include <string>

namespace hilrig::rig {

class CpuLatencyRequest {
public:
  // Asks for `max_us` microseconds of wake-up latency at most (0: stay in C0).
  explicit CpuLatencyRequest(int max_us = 0);
  ~CpuLatencyRequest();
  CpuLatencyRequest(const CpuLatencyRequest&) = delete;
  CpuLatencyRequest& operator=(const CpuLatencyRequest&) = delete;

  [[nodiscard]] bool active() const { return fd_ >= 0; }
  [[nodiscard]] const std::string& problem() const { return problem_; } // why not active

private:
  int fd_ = -1;
  std::string problem_;
};

} // namespace hilrig::rig
