#pragma once
// Test bench for the virtual SMD23E: a scheduler, the device, three input lines the test
// drives (a local stand-in for a virtual-bus line), and host-side helpers that write the
// output words the way a PLC would.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "models/smd23e/multiword.hpp"
#include "models/smd23e/smd23e.hpp"

namespace hilrig::models::smd23e::test {

using namespace hilrig::literals;

// A line the test drives; edges are delivered at the scheduler's now.
class TestLine final : public LineInput {
public:
  explicit TestLine(Scheduler& s) : sched_(s) {}
  [[nodiscard]] Level level() const override { return level_; }
  void on_edge(EdgeHandler h) override { handlers_.push_back(std::move(h)); }
  void set(Level l) {
    if (l == level_) {
      return;
    }
    level_ = l;
    for (auto& h : handlers_) {
      h(Edge{sched_.now(), l});
    }
  }

private:
  Scheduler& sched_;
  Level level_ = Level::Low;
  std::vector<EdgeHandler> handlers_;
};

struct ConfigWords {
  std::uint16_t control = 0;         // input functions and enables
  std::uint16_t word = 0x8000 | 0x7; // driver enabled, inputs active when current flows
  std::int32_t vs = 100;
  std::uint16_t steps_per_turn = 2048;
  std::uint16_t idle_percent = 50;
  std::uint16_t current10 = 20;
};

struct MoveWords {
  std::int32_t value = 0; // target / offset / stopping distance
  std::int32_t vp = 1100;
  std::uint16_t accel = 10;
  std::uint16_t decel = 10;
  std::uint16_t word8 = 0;
  std::uint16_t word9 = 0; // jerk (or Min Reg Dist lower)
};

inline constexpr std::uint16_t kDrive = lsw::kDriveEnable;

class Smd23eBench : public ::testing::Test {
protected:
  explicit Smd23eBench(Params p = {}) : dut(sched, p) {
    dut.connect_input(1, in1);
    dut.connect_input(2, in2);
    dut.connect_input(3, in3);
  }

  static Words config_block(const ConfigWords& c) {
    const MultiWord vs = encode_multiword(c.vs);
    return Words{static_cast<std::uint16_t>(msw::kConfigMode | c.control),
                 c.word,
                 vs.upper,
                 vs.lower,
                 c.steps_per_turn,
                 0,
                 1024,
                 c.idle_percent,
                 c.current10,
                 0};
  }
  // Writes a configuration, then returns to Command Mode with the driver enabled.
  void configure(const ConfigWords& c = {}) {
    dut.write_outputs(config_block(c));
    dut.write_outputs(Words{0, kDrive, 0, 0, 0, 0, 0, 0, 0, 0});
  }
  static Words block(std::uint16_t msw, std::uint16_t lsw, const MoveWords& m = {}) {
    const MultiWord v = encode_multiword(m.value);
    const MultiWord vp = encode_multiword(m.vp);
    return Words{msw, lsw, v.upper, v.lower, vp.upper, vp.lower, m.accel, m.decel, m.word8, m.word9};
  }
  // A command is a 0→1 edge: the MSW is cleared first, as the manual asks (L2403).
  void command(std::uint16_t msw, std::uint16_t lsw = kDrive, const MoveWords& m = {}) {
    Words clear = block(0, lsw, m);
    dut.write_outputs(clear);
    dut.write_outputs(block(msw, lsw, m));
  }
  void write(std::uint16_t msw, std::uint16_t lsw = kDrive, const MoveWords& m = {}) {
    dut.write_outputs(block(msw, lsw, m));
  }
  void preset(std::int32_t position) { command(msw::kPresetPosition, kDrive, MoveWords{.value = position}); }

  [[nodiscard]] std::uint16_t sw1() const { return dut.status1(); }
  [[nodiscard]] std::uint16_t sw2() const { return dut.status2(); }
  [[nodiscard]] bool bit1(std::uint16_t b) const { return (sw1() & b) != 0; }
  [[nodiscard]] bool bit2(std::uint16_t b) const { return (sw2() & b) != 0; }
  [[nodiscard]] std::int64_t position_word() const {
    const Words in = dut.input_words();
    return *decode_multiword(in[2], in[3]);
  }
  [[nodiscard]] std::int64_t encoder_word() const {
    const Words in = dut.input_words();
    return *decode_multiword(in[4], in[5]);
  }
  [[nodiscard]] std::int64_t captured_word() const {
    const Words in = dut.input_words();
    return *decode_multiword(in[6], in[7]);
  }
  // When the step train of the current run reaches a step position (exact to 1 ns).
  [[nodiscard]] Nanos when_at(std::int64_t position) const {
    const ShaftRun& r = dut.runs().back();
    const double progress = static_cast<double>((position - r.origin) * r.dir) - r.base;
    return r.motion.time_at_progress(progress);
  }
  void run_to(Nanos t) { sched.run_until(t); }
  void run_to_s(double s) { sched.run_until(Nanos::from_seconds(s)); }
  void at(Nanos t, TestLine& line, Level l) {
    sched.at(t, [&line, l] { line.set(l); });
  }

  Scheduler sched;
  TestLine in1{sched};
  TestLine in2{sched};
  TestLine in3{sched};
  Smd23e dut;
};

} // namespace hilrig::models::smd23e::test
