#include "core/skewed_output.hpp"

namespace hilrig {

SkewedOutput::SkewedOutput(Scheduler& scheduler, LineOutput& pin, Level on, Nanos off_skew)
    : scheduler_(scheduler), pin_(pin), on_(on), off_skew_(off_skew), commanded_(pin.driven()) {}

SkewedOutput::~SkewedOutput() {
  for (const Pending& p : pending_) scheduler_.cancel(p.id);
}

void SkewedOutput::set(Level level) {
  commanded_ = level;
  if (off_skew_ == Nanos{0}) { // the manual's board: both edges alike, nothing held back
    pin_.set(level);
    return;
  }
  const bool turn_on = level == on_;
  const Nanos extra = turn_on ? (off_skew_ < Nanos{0} ? -off_skew_ : Nanos{0})
                              : (off_skew_ > Nanos{0} ? off_skew_ : Nanos{0});
  const Nanos t = scheduler_.now() + extra;
  // A transition that would complete at or after this one is overtaken: it never completes.
  while (!pending_.empty() && pending_.back().time >= t) {
    scheduler_.cancel(pending_.back().id);
    pending_.pop_back();
  }
  const Level ahead = pending_.empty() ? pin_.driven() : pending_.back().level;
  if (ahead == level) return;
  if (extra == Nanos{0}) {
    pin_.set(level);
    return;
  }
  pending_.push_back(Pending{t, level, scheduler_.at(t, [this] { complete(); })});
}

void SkewedOutput::complete() {
  const Level level = pending_.front().level;
  pending_.erase(pending_.begin());
  pin_.set(level);
}

} // namespace hilrig
