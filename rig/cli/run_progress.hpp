#pragma once
// What `hilrig run` tells a person while it runs (stderr): each run as it starts
// ("[2/9] run 1 <label>", which scripts wait for), then as it ends with its outcome, its wall
// time and an estimate of the time left. Shared by the campaigns of a suite that run in
// parallel (--jobs), so it serializes its lines; in a suite each line names its campaign.

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>

#include "rig/campaign/campaign.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::cli {

class RunProgress {
public:
  enum class Mode {
    Quiet,   // nothing
    InPlace, // one line rewritten in place (stderr is a terminal)
    Lines,   // --progress: a line per run, also when stderr is a log file
  };
  RunProgress(std::ostream& err, Mode mode, std::size_t total_runs, bool name_campaigns);

  // "[3/40] run 2 point 2" (a suite: "[3/40] ans1-throughput: run 2 point 2").
  void started(std::string_view campaign, const campaign::RunSpec& run);
  // "[3/40] run 2: pass in 0.41 s; ETA 0:12" (counting finished runs).
  void finished(std::string_view campaign, const campaign::RunSpec& run, rig::Outcome outcome,
                double seconds);
  // Ends an in-place line, so what follows starts on a line of its own.
  void close();

private:
  void put(const std::string& line);

  std::ostream& err_;
  Mode mode_;
  std::size_t total_;
  bool name_campaigns_;
  std::size_t started_ = 0;
  std::size_t done_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

// "0:07", "12:30", "1:02:03": the estimate's hours only when there are some.
[[nodiscard]] std::string clock_text(double seconds);

} // namespace hilrig::cli
