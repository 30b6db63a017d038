#include "rig/duts/smd23e_dut.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/smd23e/smd23e.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

namespace m = hilrig::models::smd23e;

// While idle the shaft sensor looks for a new motion this often (motion started by the
// model itself, e.g. after a homing pause). While moving it wakes at each step's exact time.
constexpr Nanos kIdlePoll{50'000};

class Smd23eDut final : public Dut {
public:
  Smd23eDut(Scheduler& scheduler, const m::Params& params) : sched_(scheduler), device_(scheduler, params) {}
  ~Smd23eDut() override { sched_.cancel(wake_); }
  Smd23eDut(const Smd23eDut&) = delete;
  Smd23eDut& operator=(const Smd23eDut&) = delete;

  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override {
    for (const auto& [pin, line] : pin_to_line) {
      if (pin == kSmd23eStepPin) {
        step_ = &bus.line(line).driver();
      } else if (pin == kSmd23eDirPin) {
        dir_ = &bus.line(line).driver();
      } else if (pin.size() == 3 && pin.starts_with("IN") && pin[2] >= '1' && pin[2] <= '3') {
        LineInput& in = bus.line(line).reader();
        device_.connect_input(pin[2] - '0', in);
        // The model's handler runs first; then the sensor looks for motion the edge started.
        in.on_edge([this](const Edge&) { follow(); });
      } else {
        throw std::invalid_argument("smd23e has no pin " + pin);
      }
    }
    follow();
  }

  void host_write(std::size_t word, std::uint16_t value) override {
    if (word >= m::kWords) throw std::out_of_range("smd23e has 10 output words");
    staged_[word] = value;
    if (word == 0) {
      device_.write_outputs(staged_);
      follow();
    }
  }

  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override {
    if (word >= m::kWords) throw std::out_of_range("smd23e has 10 input words");
    return device_.input_words()[word];
  }

private:
  // Emits the steps the shaft has turned since the last call, then sleeps until the next.
  void follow() {
    sched_.cancel(wake_);
    const Nanos now = sched_.now();
    const std::int64_t here = device_.shaft_steps(now);
    while (emitted_ != here) {
      const bool cw = here > emitted_;
      if (dir_ != nullptr && cw != dir_cw_) dir_->set(level_of(cw));
      dir_cw_ = cw;
      step_level_ = !step_level_;
      if (step_ != nullptr) step_->set(step_level_);
      emitted_ += cw ? 1 : -1;
    }
    wake_ = sched_.at(next_wake(now), [this] { follow(); });
  }

  // The exact time the present run issues its next whole step (the model issues a step when
  // the continuous profile crosses a whole step), or the idle poll, whichever is sooner.
  [[nodiscard]] Nanos next_wake(Nanos now) const {
    Nanos next = now + kIdlePoll;
    if (!device_.moving() || device_.runs().empty()) return next;
    const m::ShaftRun& r = device_.runs().back();
    const double progress = r.base + r.motion.progress(now);
    const double k = std::floor(progress + 1e-6) + 1.0;
    const Nanos t = r.motion.time_at_progress(k - r.base);
    if (t <= now) return now + Nanos{1};
    return t < next ? t : next;
  }

  Scheduler& sched_;
  m::Smd23e device_;
  m::Words staged_{};
  LineOutput* step_ = nullptr;
  LineOutput* dir_ = nullptr;
  Level step_level_ = Level::Low;
  bool dir_cw_ = false;
  std::int64_t emitted_ = 0;
  EventId wake_{};
};

} // namespace

DutInfo smd23e_info() {
  DutInfo info;
  info.name = "smd23e";
  info.description = "AMCI SMD23E integrated stepper indexer/driver/motor (virtual model, spec/smd23e.md)";
  for (int i = 1; i <= 3; ++i)
    info.pins.push_back({"IN" + std::to_string(i), PinDirection::Input,
                         "discrete input " + std::to_string(i) + " (High = current flows)", false});
  info.pins.push_back({kSmd23eStepPin, PinDirection::Output,
                       "shaft sensor: one edge (either level) per step the shaft turns", false});
  info.pins.push_back({kSmd23eDirPin, PinDirection::Output,
                       "shaft sensor: High while the shaft steps CW, Low CCW (Low at power-up)", false});
  const m::Params d{};
  // Ranges: the homing pause is 2 s (spec/smd23e.md T2, L136; manual L1327): 0 .. 60 s; an input
  // delay [A] 0 .. 1 s; the fault knobs within what keeps a move a move (1 lost step in 1 ..
  // 1,000,000; ramps at 0.01 .. 100 x A and D; stops 0 .. 10 s late).
  info.params = {
      {"homing_pause", ParamKind::Duration, d.homing_pause, "pause between homing stops (T2, 2 s)",
       between(0_us, 60_s)},
      {"input_delay", ParamKind::Duration, d.input_delay, "input edge to effect [A] (0)", between(0_us, 1_s)},
      {"has_encoder", ParamKind::Boolean, d.has_encoder, "an E unit (internal 1024-count encoder)", {}},
      {"flash_config_valid",
       ParamKind::Boolean,
       d.flash_config_valid,
       "power up configured from flash (v_s 100, 2048 steps/turn)",
       {}},
      {"late_stop_delay", ParamKind::Duration, d.late_stop_delay, "variant late-stop: how late stops act",
       between(0_us, 10_s)},
      {"lost_step_interval", ParamKind::Integer, d.lost_step_interval,
       "variant lost-steps: one step lost in this many", between(1.0, 1'000'000.0)},
      {"wrong_accel_factor", ParamKind::Number, d.wrong_accel_factor,
       "variant wrong-acceleration: ramps at this x A and D", between(0.01, 100.0)},
  };
  info.variants.push_back({"nominal", "as specified"});
  for (const std::string_view v : m::fault_names())
    info.variants.push_back({std::string(v), "wrong on purpose (models/smd23e/README.md)"});
  info.host = HostInterface{m::kWords, m::kWords, false, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t /*seed*/) -> std::unique_ptr<Dut> {
    m::Params p;
    p.homing_pause = params.duration("homing_pause");
    p.input_delay = params.duration("input_delay");
    p.has_encoder = params.boolean("has_encoder");
    p.flash_config_valid = params.boolean("flash_config_valid");
    p.late_stop_delay = params.duration("late_stop_delay");
    p.lost_step_interval = params.integer("lost_step_interval");
    p.wrong_accel_factor = params.number("wrong_accel_factor");
    if (variant != "nominal") {
      const auto f = m::fault_from_name(variant);
      if (!f) throw std::invalid_argument("smd23e has no variant " + std::string(variant));
      p.fault = *f;
    }
    return std::make_unique<Smd23eDut>(scheduler, p);
  };
  return info;
}

} // namespace hilrig::duts
