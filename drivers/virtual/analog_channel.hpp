#pragma once
// A virtual analog channel: its value is a function of time set by the driving side
// (a Waveform); readers sample it at any instant.

#include <string>

#include "core/analog.hpp"

namespace hilrig::virt {

class AnalogChannel final : public AnalogInput {
public:
  explicit AnalogChannel(std::string name) : name_(std::move(name)) {}
  void set_waveform(Waveform w) { waveform_ = std::move(w); }
  [[nodiscard]] double sample(Nanos t) const override { return waveform_ ? waveform_(t) : 0.0; }
  [[nodiscard]] const std::string& name() const { return name_; }

private:
  std::string name_;
  Waveform waveform_;
};

} // namespace hilrig::virt
