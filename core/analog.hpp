#pragma once
// Analog channels: a value that is a function of time, sampled by a reader at any
// instant (no fixed sample rate). A resolver's two stator signals are two of these.

#include <functional>

#include "core/time.hpp"

namespace hilrig {

class AnalogInput {
public:
  virtual ~AnalogInput() = default;
  [[nodiscard]] virtual double sample(Nanos t) const = 0;

  // Sampling ahead of time (a model skipping its scans, docs/virtual-time.md): true when what
  // sample(t) gives now for any t from now on stays so until the channel announces a revision
  // to the handlers of on_revision. False (the default): the future is not known, so a reader
  // must sample at the time.
  [[nodiscard]] virtual bool announces_revisions() const { return false; }
  // `handler` runs whenever the values from now on may have changed (and when the channel
  // stops announcing them). A channel that never announces never calls it.
  virtual void on_revision(std::function<void()> handler) { (void)handler; }
};

using Waveform = std::function<double(Nanos)>;

} // namespace hilrig
