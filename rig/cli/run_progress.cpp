#include "rig/cli/run_progress.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

namespace hilrig::cli {

RunProgress::RunProgress(std::ostream& err, Mode mode, std::size_t total_runs, bool name_campaigns)
    : err_(err), mode_(mode), total_(total_runs), name_campaigns_(name_campaigns),
      start_(std::chrono::steady_clock::now()) {}

void RunProgress::put(const std::string& line) {
  if (mode_ == Mode::InPlace)
    err_ << '\r' << line << "\x1b[K" << std::flush;
  else if (mode_ == Mode::Lines)
    err_ << line << '\n' << std::flush;
}

void RunProgress::started(std::string_view campaign, const campaign::RunSpec& run) {
  const std::lock_guard lock(mutex_);
  ++started_;
  put(fmt::format("[{}/{}] {}{}run {} {}", started_, total_, name_campaigns_ ? campaign : "",
                  name_campaigns_ ? ": " : "", run.index, run.label));
}

std::string clock_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(std::max(seconds, 0.0)));
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

void RunProgress::finished(std::string_view campaign, const campaign::RunSpec& run, rig::Outcome outcome,
                           double seconds) {
  const std::lock_guard lock(mutex_);
  ++done_;
  if (mode_ == Mode::Quiet) return;
  // The wall time so far per finished run, times the runs left: with --jobs N the campaigns
  // overlap, and elapsed time (not the sum of run times) is what the estimate must scale.
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta =
      elapsed / static_cast<double>(done_) * static_cast<double>(total_ - std::min(done_, total_));
  put(fmt::format("[{}/{}] {}{}run {}: {} in {:.2f} s; ETA {}", done_, total_,
                  name_campaigns_ ? campaign : "", name_campaigns_ ? ": " : "", run.index,
                  rig::to_string(outcome), seconds, clock_text(eta)));
}

void RunProgress::close() {
  const std::lock_guard lock(mutex_);
  if (mode_ == Mode::InPlace && done_ > 0) err_ << '\n' << std::flush;
}

} // namespace hilrig::cli
