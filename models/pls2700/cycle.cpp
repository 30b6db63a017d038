#include "models/pls2700/cycle.hpp"

namespace hilrig::models::pls2700 {

void CycleLogic::set_trigger(Trigger trigger) {
  pending_ = trigger;
  if (!cycling_) {
    trigger_ = trigger;
  }
}

void CycleLogic::start() {
  cycling_ = true;
  last_ = false;
  ls_ = 0;
}

void CycleLogic::stop() {
  cycling_ = false;
  last_ = false;
  trigger_ = pending_;
}

void CycleLogic::end_of_cycle(int cycle_length) {
  if (!cycling_ || ls_ < cycle_length) {
    return;
  }
  if (level_mode() && !last_) {
    ls_ %= cycle_length; // the input is still active: the next cycle starts at once
    return;
  }
  stop();
}

void CycleLogic::input(Level level) {
  if (level_mode()) {
    if (!cycling_) {
      if (active(level)) {
        start();
      }
    } else if (!active(level)) {
      last_ = true; // this cycle is the last; a return to active during it is ignored
    }
    return;
  }
  if (!cycling_ && active(level)) {
    start(); // the programmed edge; edges during a cycle are not queued
  }
}

} // namespace hilrig::models::pls2700
