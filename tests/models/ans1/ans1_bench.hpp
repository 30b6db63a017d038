#pragma once
// A small bench for the ANS1 device tests: a virtual bus, the device wired to it by line
// name, quadrature and resolver stimulus, and the output edges captured with their times.
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <ostream>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/ans1/ans1.hpp"
#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_waveform.hpp"

namespace hilrig {
// Readable times and edges in test failures.
inline void PrintTo(const Nanos& t, std::ostream* os) { *os << t.count() << " ns"; }
inline void PrintTo(const Edge& e, std::ostream* os) {
  *os << (is_high(e.level) ? "rise" : "fall") << " at " << e.time.count() << " ns";
}
} // namespace hilrig

namespace hilrig::models::ans1::testing {

class Bench {
public:
  // With a waveform, the device samples the encoder from it (Ans1Pins::quad_waveform); the
  // A/B lines carry the same edges only when play() plays them.
  explicit Bench(const Params& params = {}, Variant variant = Variant::Correct,
                 signals::QuadratureWaveform* waveform = nullptr)
      : bus_(scheduler_), device_(scheduler_, pins(bus_, waveform), params, variant) {
    for (int n = 1; n <= kOutputCount; ++n) {
      bus_.line("ans1." + output_pin_name(n)).reader().on_edge([this, n](const Edge& e) {
        edges_[static_cast<std::size_t>(n - 1)].push_back(e);
      });
    }
  }

  Scheduler& scheduler() { return scheduler_; }
  virt::VirtualBus& bus() { return bus_; }
  Ans1& device() { return device_; }
  const std::vector<Edge>& edges(int output) const { return edges_[static_cast<std::size_t>(output - 1)]; }
  Level pin(int output) { return bus_.line("ans1." + output_pin_name(output)).level(); }
  void run_until(Nanos t) { scheduler_.run_until(t); }

  // Discrete input n: High = current flows.
  void set_input(int n, bool on) { bus_.line("ans1." + input_pin_name(n)).driver().set(level_of(on)); }
  void input_at(Nanos t, int n, bool on) {
    scheduler_.at(t, [this, n, on] { set_input(n, on); });
  }

  // Quadrature count steps at explicit times: from the present count, one step (+1 or -1)
  // at each time. Forward is A leading B.
  void quadrature_steps(const std::vector<Nanos>& times, int direction) {
    for (Nanos t : times) {
      scheduler_.at(t, [this, direction] { step_quadrature(direction); });
    }
  }
  // `count` steps at a constant period, the first at first.
  void quadrature_run(Nanos first, Nanos period, std::int64_t count, int direction) {
    for (std::int64_t k = 0; k < count; ++k) {
      scheduler_.at(first + period * k, [this, direction] { step_quadrature(direction); });
    }
  }
  // Every A/B edge of a solved motion on the lines, at its time.
  void play(const signals::QuadratureTrace& trace) {
    for (const signals::QuadEdge& e : trace.edges) {
      if (e.channel != signals::QuadChannel::Z) {
        const bool on_a = e.channel == signals::QuadChannel::A;
        scheduler_.at(e.time, [this, on_a, level = e.level] {
          bus_.line(on_a ? "ans1.A" : "ans1.B").driver().set(level);
        });
      }
    }
  }
  void step_quadrature(int direction) {
    phase_ = (phase_ + (direction > 0 ? 1 : 3)) % 4;
    static constexpr std::array<std::pair<bool, bool>, 4> kStates{
        {{false, false}, {true, false}, {true, true}, {false, true}}};
    const auto [a, b] = kStates[static_cast<std::size_t>(phase_)];
    bus_.line("ans1.A").driver().set(level_of(a));
    bus_.line("ans1.B").driver().set(level_of(b));
  }

  // Resolver stator signals for a shaft angle given in 4096-count units as a function of
  // time: TR * ref(t) * sin / cos (spec §2.1), locked to the device's excitation.
  void resolver(std::function<double(Nanos)> counts, double tr = 0.95) {
    const ResolverExcitation& ex = device_.excitation();
    auto angle = std::make_shared<std::function<double(Nanos)>>(std::move(counts));
    bus_.analog("ans1.SIN").set_waveform([&ex, angle, tr](Nanos t) {
      return tr * ex.value(t) * std::sin(2.0 * std::numbers::pi * (*angle)(t) / 4096.0);
    });
    bus_.analog("ans1.COS").set_waveform([&ex, angle, tr](Nanos t) {
      return tr * ex.value(t) * std::cos(2.0 * std::numbers::pi * (*angle)(t) / 4096.0);
    });
  }
  void resolver_at(double counts, double tr = 0.95) {
    resolver([counts](Nanos) { return counts; }, tr);
  }

  // The first edge of `output` to `level` at or after `from`.
  std::optional<Nanos> first_edge(int output, Level level, Nanos from = Nanos::zero()) const {
    for (const Edge& e : edges(output)) {
      if (e.time >= from && e.level == level) {
        return e.time;
      }
    }
    return std::nullopt;
  }

private:
  static Ans1Pins pins(virt::VirtualBus& bus, signals::QuadratureWaveform* waveform) {
    Ans1Pins p = wire_pins(bus);
    p.quad_waveform = waveform;
    return p;
  }

  Scheduler scheduler_;
  virt::VirtualBus bus_;
  Ans1 device_;
  std::array<std::vector<Edge>, kOutputCount> edges_{};
  int phase_ = 0;
};

// Encoder setup with raw count = GMP: CPC = FSC.
inline PositionSetup encoder_setup(std::uint16_t cpc, std::uint16_t fsc) {
  PositionSetup s;
  s.sensor = SensorType::Quadrature;
  s.counts_per_cycle = cpc;
  s.full_scale_count = fsc;
  return s;
}

inline OutputSetup pair_output(std::uint16_t from, std::uint16_t to) {
  OutputSetup o;
  o.pairs[0] = SetpointPair{from, to, 0, 0};
  return o;
}

// The scan-every-period oracle of exact scan skipping (docs/virtual-time.md).
inline Params every_period() {
  Params p;
  p.exact_scan = true;
  return p;
}

} // namespace hilrig::models::ans1::testing
