#pragma once
// A test bench for the virtual 4501 wired as the rig wires it: encoder A/B/Z, Start and
// Latch driven on the virtual bus, the Cycle Output captured with timestamps, and the host
// words. Encoder motion is synthesized with the signals library (a motion profile in X4
// counts, its edges solved in closed form); Start/Latch are DiscreteSignals.
//
// Conventions follow docs/spec/amci4501-examples.md §0: times in us from t = 0, encoder
// bursts F(n, t0, dt) / R(n, t0, dt) = n X4 edges at t0, t0 + dt, ..., 1,024-line encoder.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/amci4501/amci4501.hpp"
#include "signals/discrete_input.hpp"
#include "signals/edge_rate.hpp"
#include "signals/motion_profile.hpp"
#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"

namespace hilrig::models::amci4501::test {

using namespace hilrig::literals;

[[nodiscard]] inline Nanos us(std::int64_t n) { return microseconds(n); }

// Encoder motion as bursts of evenly spaced X4 edges with rests between (a profile in
// counts: the edge to state k + 1 sits at position k + 0.5, quadrature_encoder.hpp).
class EncoderMotion {
public:
  EncoderMotion() : profile_(0.0, Nanos{0}) {}
  // n edges (negative: reverse, B leads A), the first at t0, then every dt.
  EncoderMotion& burst(std::int64_t n, Nanos t0, Nanos dt) {
    const Nanos begin = t0 - dt / 2;
    if (begin > profile_.end_time()) signals::constant_speed(profile_, 0.0, begin - profile_.end_time());
    const double v = (n < 0 ? -1.0 : 1.0) / dt.seconds();
    signals::constant_speed(profile_, v, dt * (n < 0 ? -n : n));
    return *this;
  }
  [[nodiscard]] const signals::MotionProfile& profile() const { return profile_; }
  [[nodiscard]] static signals::QuadratureEncoder encoder() {
    signals::QuadratureEncoder e;
    e.lines_per_turn = 1024;   // examples §0.2: 4,096 X4 counts per turn
    e.units_per_turn = 4096.0; // the profile is in counts
    return e;
  }

private:
  signals::MotionProfile profile_;
};

struct CapturedEdge {
  Nanos time;
  bool on;
};

class Bench {
public:
  explicit Bench(Params params = {}, Level start_idle = Level::Low, Level latch_idle = Level::Low)
      : bus_(scheduler), a_(bus_.line("enc.a")), b_(bus_.line("enc.b")), z_(bus_.line("enc.z")),
        start_(bus_.line("start", start_idle)), latch_(bus_.line("latch", latch_idle)),
        cycle_(bus_.line("cycle_output")) {
    cycle_.reader().on_edge([this](const Edge& e) {
      cycle_edges.push_back({e.time, e.level == params_.cycle_output_on});
    });
    params_ = params;
    module = std::make_unique<Amci4501>(
        scheduler,
        Pins{a_.reader(), b_.reader(), start_.reader(), latch_.reader(), cycle_.driver(), &z_.reader()},
        params);
  }

  // ---- stimulus ----
  // Appends a burst to the encoder's motion and plays its A/B edges onto the lines at
  // their solved times. The rig keeps each channel within the 4501's 250 kHz (L271); the
  // bench insists on it. Bursts must come in time order.
  void burst(std::int64_t n, Nanos t0, Nanos dt) {
    motion_.burst(n, t0, dt);
    const auto enc = EncoderMotion::encoder();
    signals::check_edge_rate(motion_.profile(), enc, 250'000.0, signals::RateLimitAction::Fail);
    const Nanos from = played_until_;
    signals::for_each_quadrature_edge(motion_.profile(), enc, [this, from](const signals::QuadEdge& e) {
      if (e.time < from || e.channel == signals::QuadChannel::Z) return;
      virt::DigitalLine* line = e.channel == signals::QuadChannel::A ? &a_ : &b_;
      const Level level = e.level;
      scheduler.at(e.time, [line, level] { line->driver().set(level); });
    });
    played_until_ = motion_.profile().end_time();
  }
  void play_start(const signals::DiscreteSignal& s) { play_discrete(start_, s); }
  void play_latch(const signals::DiscreteSignal& s) { play_discrete(latch_, s); }
  void start_at(Nanos t, Level level) { drive_at(start_, t, level); }
  void latch_at(Nanos t, Level level) { drive_at(latch_, t, level); }
  void start_pulse(Nanos t, Nanos width) { play_start(signals::DiscreteSignal{}.pulse(t, width)); }
  void latch_pulse(Nanos t, Nanos width) { play_latch(signals::DiscreteSignal{}.pulse(t, width)); }
  void z_pulse(Nanos t, Nanos width) { play_discrete(z_, signals::DiscreteSignal{}.pulse(t, width)); }

  // ---- host ----
  // A complete programming cycle (L168) at the current time: words 1-7 and the control
  // word with Transmit, then Transmit cleared once Acknowledge is seen.
  void program(std::uint16_t control_word, std::array<std::uint16_t, 7> rest = {}) {
    std::array<std::uint16_t, 8> w{};
    w[0] = static_cast<std::uint16_t>(control_word | control::kTransmit);
    std::copy(rest.begin(), rest.end(), w.begin() + 1);
    module->write_output_words(0, w);
    ack_seen = (module->status() & status::kAcknowledge) != 0;
    module->write_output(0, static_cast<std::uint16_t>(control_word & ~control::kTransmit));
  }
  void program_mode(int mode, std::uint16_t timeout_ms = 1000) {
    program(mode_select_bit(mode), {timeout_ms});
  }
  void program_window(std::uint32_t on, std::uint32_t off, std::uint16_t timeout_ms = 1000) {
    program(control::kMode2,
            {timeout_ms, static_cast<std::uint16_t>(on / 1000), static_cast<std::uint16_t>(on % 1000),
             static_cast<std::uint16_t>(off / 1000), static_cast<std::uint16_t>(off % 1000)});
  }
  // Host writes at time t (from inside the run, as the host's scan would).
  void write_at(Nanos t, std::uint16_t control_word) {
    scheduler.at(t, [this, control_word] { module->write_output(0, control_word); });
  }
  // Host policy H (examples §0.2): every `scan`, acknowledge a new result (set O:0/0) and
  // clear O:0/0 once I:0/0 has dropped.
  void prompt_host(Nanos scan = 1_ms) {
    scheduler.after(scan, [this, scan] {
      const std::uint16_t out = module->output_words()[0];
      if ((module->status() & status::kNewValue) != 0 && (out & control::kReceived) == 0)
        module->write_output(0, static_cast<std::uint16_t>(out | control::kReceived));
      else if ((module->status() & status::kNewValue) == 0 && (out & control::kReceived) != 0)
        module->write_output(0, static_cast<std::uint16_t>(out & ~control::kReceived));
      prompt_host(scan);
    });
  }

  void run_until(Nanos t) { scheduler.run_until(t); }
  [[nodiscard]] InputWords words() const { return module->input_words(); }
  [[nodiscard]] std::uint16_t word(std::size_t i) const { return module->input_words().at(i); }
  [[nodiscard]] std::uint16_t status() const { return module->status(); }
  [[nodiscard]] bool bit(std::uint16_t mask) const { return (module->status() & mask) != 0; }

  Scheduler scheduler;
  std::vector<CapturedEdge> cycle_edges;
  std::unique_ptr<Amci4501> module;
  bool ack_seen = false;

private:
  void play_discrete(virt::DigitalLine& line, const signals::DiscreteSignal& s) {
    for (const Edge& e : s.edges()) drive_at(line, e.time, e.level);
  }
  void drive_at(virt::DigitalLine& line, Nanos t, Level level) {
    virt::DigitalLine* l = &line;
    scheduler.at(t, [l, level] { l->driver().set(level); });
  }

  virt::VirtualBus bus_;
  virt::DigitalLine& a_;
  virt::DigitalLine& b_;
  virt::DigitalLine& z_;
  virt::DigitalLine& start_;
  virt::DigitalLine& latch_;
  virt::DigitalLine& cycle_;
  Params params_;
  EncoderMotion motion_;
  Nanos played_until_{0};
};

} // namespace hilrig::models::amci4501::test
