#pragma once
// A virtual analog channel: its value is a function of time set by the driving side
// (a Waveform); readers sample it at any instant.

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/analog.hpp"

namespace hilrig::virt {

class AnalogChannel final : public AnalogInput {
public:
  // What the driving side promises about a waveform's future (AnalogInput::announces_revisions):
  // Unknown, nothing; Fixed, a pure function of time; Revised, the driver calls revise() whenever
  // the values from now on change (a waveform following frames as they arrive).
  enum class Future : std::uint8_t { Unknown, Fixed, Revised };

  explicit AnalogChannel(std::string name) : name_(std::move(name)) {}
  // A new waveform is itself a revision.
  void set_waveform(Waveform w, Future future = Future::Unknown) {
    waveform_ = std::move(w);
    future_ = future;
    revise();
  }
  [[nodiscard]] double sample(Nanos t) const override { return waveform_ ? waveform_(t) : 0.0; }
  [[nodiscard]] const std::string& name() const { return name_; }

  [[nodiscard]] bool announces_revisions() const override { return future_ != Future::Unknown; }
  void on_revision(std::function<void()> handler) override {
    revision_handlers_.push_back(std::move(handler));
  }
  void revise() const {
    for (const auto& h : revision_handlers_) h();
  }

private:
  std::string name_;
  Waveform waveform_;
  Future future_ = Future::Unknown;
  std::vector<std::function<void()>> revision_handlers_;
};

} // namespace hilrig::virt
