#include "models/ans1/production_counters.hpp"

namespace hilrig::models::ans1 {

namespace {
constexpr std::uint64_t kModulus = static_cast<std::uint64_t>(kCounterMax) + 1;

[[nodiscard]] std::uint16_t bit(int point) { return static_cast<std::uint16_t>(1U << (point - 1)); }

// True when moving forward from `from` by `step` counts reaches `target` (from excluded).
[[nodiscard]] bool reaches(std::uint16_t from, std::uint32_t step, std::uint16_t target, std::uint16_t fsc) {
  const std::uint32_t distance = (static_cast<std::uint32_t>(target) + fsc - from) % fsc;
  return distance != 0 && distance <= step;
}
} // namespace

void ProductionCounters::configure(const ProductionSetup& setup, std::uint16_t full_scale_count) {
  if (setup.multiplier != setup_.multiplier || setup.divisor != setup_.divisor) {
    part_base_ = values_[idx(CounterId::PartCycle)];
    part_events_ = 0;
  }
  for (std::size_t i = 0; i < overflow_.size(); ++i) {
    if (setup.counters[i].overflow_mode == OverflowMode::None) overflow_[i] = false;
  }
  setup_ = setup;
  if (full_scale_count != fsc_) primed_ = false;
  fsc_ = full_scale_count == 0 ? 1 : full_scale_count;
}

void ProductionCounters::preset(CounterId counter, std::uint32_t value) {
  values_[idx(counter)] = value;
  if (counter == CounterId::PartCycle) {
    part_base_ = value;
    part_events_ = 0;
  }
}

void ProductionCounters::advance(CounterId c, std::uint32_t step) {
  const std::uint32_t before = values_[idx(c)];
  values_[idx(c)] = static_cast<std::uint32_t>((static_cast<std::uint64_t>(before) + step) % kModulus);
  const CounterSetup& cs = setup_.counters[idx(c)];
  if (cs.limit == 0 || cs.overflow_mode == OverflowMode::None) return;
  if (before < cs.limit && static_cast<std::uint64_t>(before) + step >= cs.limit) {
    overflow_[idx(c)] = cs.overflow_mode == OverflowMode::Toggle ? !overflow_[idx(c)] : true;
  }
}

bool ProductionCounters::update(std::uint16_t gmp, bool dp_fault_in_cycle) {
  if (!primed_) {
    primed_ = true;
    last_gmp_ = gmp;
    return false;
  }
  const std::uint16_t from = last_gmp_;
  last_gmp_ = gmp;
  const std::uint32_t step = (static_cast<std::uint32_t>(gmp) + fsc_ - from) % fsc_;
  if (step == 0 || 2 * step > fsc_) return false; // no motion, or reverse motion

  if (reaches(from, step, 0, fsc_)) advance(CounterId::Revolutions, 1); // L1215
  if (!reaches(from, step, setup_.increment_position, fsc_)) return false;

  // A new production cycle starts: mode-1 overflow outputs return inactive (L1224).
  for (std::size_t i = 0; i < overflow_.size(); ++i) {
    if (setup_.counters[i].overflow_mode == OverflowMode::ActiveUntilNextCycle) overflow_[i] = false;
  }
  const std::uint32_t before = values_[idx(CounterId::PartCycle)];
  ++part_events_;
  const std::uint64_t scaled = part_events_ * setup_.multiplier / setup_.divisor;
  const std::uint32_t after = static_cast<std::uint32_t>((part_base_ + scaled) % kModulus);
  const std::uint32_t delta = static_cast<std::uint32_t>((after + kModulus - before) % kModulus);
  values_[idx(CounterId::PartCycle)] = before; // advance() applies the step and the limit rule
  advance(CounterId::PartCycle, delta);
  for (CounterId batch : {CounterId::Batch1, CounterId::Batch2, CounterId::Batch3}) {
    if (!setup_.counters[idx(batch)].only_good_cycles || !dp_fault_in_cycle) advance(batch, delta);
  }
  if (!dp_fault_in_cycle) advance(CounterId::GoodPart, delta); // L1207
  return true;
}

std::uint16_t ProductionCounters::overflow_output_mask() const {
  std::uint16_t mask = 0;
  for (const CounterSetup& cs : setup_.counters) {
    if (cs.overflow_output != 0 && cs.overflow_mode != OverflowMode::None)
      mask = static_cast<std::uint16_t>(mask | bit(cs.overflow_output));
  }
  return mask;
}

std::uint16_t ProductionCounters::overflow_output_levels() const {
  std::uint16_t levels = 0;
  for (std::size_t i = 0; i < overflow_.size(); ++i) {
    levels = static_cast<std::uint16_t>(levels | overflow_state_mask(static_cast<CounterId>(i)));
  }
  return levels;
}

std::uint16_t ProductionCounters::overflow_state_mask(CounterId c) const {
  const CounterSetup& cs = setup_.counters[idx(c)];
  if (cs.overflow_output == 0 || cs.overflow_mode == OverflowMode::None || !overflow_[idx(c)]) return 0;
  return bit(cs.overflow_output);
}

} // namespace hilrig::models::ans1
