#pragma once
// 2742-18 trigger and cycle logic of one channel (pls2700.md §4.11, Appendix A). An input
// trigger starts an LS Position at 0 that follows the machine's forward motion; the
// channel's outputs are evaluated on it instead of on MP. Edge mode runs one cycle per
// programmed edge and ignores edges during it (R-18-3); level mode repeats cycles while the
// input stays active, and a started cycle always completes (R-18-4).
#include "core/line.hpp"
#include "models/pls2700/setup.hpp"

namespace hilrig::models::pls2700 {

class CycleLogic {
public:
  // Polarity/trigger changes while a cycle runs wait for its end (L1512).
  void set_trigger(Trigger trigger);
  [[nodiscard]] Trigger trigger() const { return trigger_; }

  // Order within an update tick: advance(), end_of_cycle(), then input() for each edge.
  // R-18-5: LS follows the accumulated MP motion since the trigger.
  void advance(int mp_step) {
    if (cycling_) {
      ls_ += mp_step;
    }
  }
  void end_of_cycle(int cycle_length);
  void input(Level level);

  [[nodiscard]] bool cycling() const { return cycling_; }
  [[nodiscard]] int ls_position() const { return ls_; }
  // Level mode, input still active: another cycle follows this one (R-18-6 anticipation).
  [[nodiscard]] bool another_cycle_follows() const { return cycling_ && level_mode() && !last_; }
  [[nodiscard]] bool level_mode() const {
    return trigger_ == Trigger::PositiveLevel || trigger_ == Trigger::NegativeLevel;
  }
  void stop();

private:
  [[nodiscard]] bool active(Level level) const {
    const bool positive = trigger_ == Trigger::PositiveEdge || trigger_ == Trigger::PositiveLevel;
    return is_high(level) == positive;
  }
  void start();

  Trigger trigger_ = Trigger::PositiveEdge;
  Trigger pending_ = Trigger::PositiveEdge;
  bool cycling_ = false;
  bool last_ = false;
  int ls_ = 0;
};

} // namespace hilrig::models::pls2700
