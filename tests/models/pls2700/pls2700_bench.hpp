#pragma once
// A bench for the 2700 tests, as the rig drives the module: a virtual bus, the device wired
// by line name ("pls.SIN1", "pls.OUT3", ...), resolver stator waveforms locked to the
// module's own reference, host BTW/BTR words, and the output edges captured with their times.
#include <array>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <ostream>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/pls2700/bcd.hpp"
#include "models/pls2700/pls2700.hpp"
#include "signals/motion_profile.hpp"
#include "signals/resolver.hpp"

namespace hilrig {
inline void PrintTo(const Nanos& t, std::ostream* os) { *os << t.count() << " ns"; }
} // namespace hilrig

namespace hilrig::models::pls2700::testing {

using namespace hilrig::literals;

class Bench {
public:
  explicit Bench(ModelVariant model, const Params& params = {}, Fault fault = Fault::Nominal)
      : bus_(scheduler_), device_(scheduler_, wire_pins(bus_, "pls."), model, params, fault) {
    for (int n = 1; n <= kOutputCount; ++n) {
      bus_.line("pls." + output_pin_name(n)).reader().on_edge([this, n](const Edge& e) {
        edges_[static_cast<std::size_t>(n - 1)].push_back(e);
      });
    }
  }

  Scheduler& scheduler() { return scheduler_; }
  virt::VirtualBus& bus() { return bus_; }
  Pls2700& device() { return device_; }
  void run_until(Nanos t) { scheduler_.run_until(t); }
  void run_for(Nanos d) { scheduler_.run_until(scheduler_.now() + d); }

  // The shaft of channel `channel` at angle(t) turns: the stator windings carry
  // TR * ref(t) * sin/cos(2 pi angle) in phase with the module's reference (§2.4).
  signals::Resolver& shaft(int channel, signals::AngleFunction angle, double tr = 1.0) {
    auto& r = resolvers_[static_cast<std::size_t>(channel - 1)];
    r.emplace_back(device_.excitation().resolver_params(tr), std::move(angle));
    bus_.analog("pls." + sin_pin_name(channel)).set_waveform(r.back().sin_waveform());
    bus_.analog("pls." + cos_pin_name(channel)).set_waveform(r.back().cos_waveform());
    return r.back();
  }
  // The shaft held at the centre of count k of a scale factor (§2.3: any sane rounding
  // then reads k).
  signals::Resolver& hold(int channel, int k, int scale_factor) {
    const double turns = (static_cast<double>(k) + 0.5) / static_cast<double>(scale_factor);
    return shaft(channel, [turns](Nanos) { return turns; });
  }
  // A motion profile in turns.
  signals::Resolver& profile(int channel, signals::MotionProfile p) {
    return shaft(channel, signals::angle_from_profile(std::move(p), 1.0));
  }

  std::uint8_t btw(std::initializer_list<std::uint16_t> words) {
    const std::vector<std::uint16_t> w(words);
    return device_.write_btw(w);
  }
  std::vector<std::uint16_t> btr() {
    std::vector<std::uint16_t> out(device_.btr_words());
    device_.read_btr(out);
    return out;
  }
  void input(int channel, bool on) { bus_.line("pls." + input_pin_name(channel)).driver().set(level_of(on)); }
  void input_at(Nanos t, int channel, bool on) {
    scheduler_.at(t, [this, channel, on] { input(channel, on); });
  }

  const std::vector<Edge>& edges(int output) const { return edges_[static_cast<std::size_t>(output - 1)]; }
  bool pin(int output) { return is_high(bus_.line("pls." + output_pin_name(output)).level()); }

private:
  Scheduler scheduler_;
  virt::VirtualBus bus_;
  Pls2700 device_;
  std::array<std::vector<Edge>, kOutputCount> edges_{};
  std::array<std::deque<signals::Resolver>, 2> resolvers_{};
};

} // namespace hilrig::models::pls2700::testing
