#include "rig/duts/reference_pls.hpp"
#include "rig/duts/seed_phase.hpp"

#include <stdexcept>

#include "drivers/virtual/virtual_bus.hpp"

namespace hilrig::duts {

using namespace hilrig::literals;

namespace {

// X4 quadrature: the Gray sequence 00 -> 10 -> 11 -> 01 (A,B) counts up (A leads B).
// Index by (old << 2) | new; both bits changing is illegal and counts nothing.
constexpr std::array<int, 16> kStep = {
    0,  -1, +1, 0,  // from 00: to 01 is backwards, to 10 forwards
    +1, 0,  0,  -1, // from 01: to 00 forwards, to 11 backwards
    -1, 0,  0,  +1, // from 10: to 00 backwards, to 11 forwards
    0,  +1, -1, 0,  // from 11: to 01 forwards, to 10 backwards
};

std::uint16_t low_word(std::int64_t v) {
  return static_cast<std::uint16_t>(static_cast<std::uint64_t>(v) & 0xFFFFU);
}

} // namespace

ReferencePls::ReferencePls(Scheduler& scheduler, Config config)
    : scheduler_(scheduler), config_(config), count_(config.preset) {
  if (config_.scan <= Nanos{0}) throw std::invalid_argument("reference_pls: scan must be > 0");
  if (config_.delay < Nanos{0}) throw std::invalid_argument("reference_pls: delay must be >= 0");
  if (config_.phase < Nanos{0} || config_.phase >= config_.scan)
    throw std::invalid_argument("reference_pls: phase must be in [0, scan)");
  scheduler_.at(scheduler_.now() + config_.phase + config_.scan, [this] { scan(); });
}

void ReferencePls::attach(virt::VirtualBus& bus,
                          const std::map<std::string, std::string, std::less<>>& pin_to_line) {
  for (const auto& [pin, line] : pin_to_line) {
    if (pin == "A") {
      a_ = &bus.line(line).reader();
      a_->on_edge([this](const Edge&) { on_quadrature(); });
    } else if (pin == "B") {
      b_ = &bus.line(line).reader();
      b_->on_edge([this](const Edge&) { on_quadrature(); });
    } else if (pin == "EN") {
      en_ = &bus.line(line).reader();
      en_->on_edge([this](const Edge& e) { on_enable(e); });
    } else if (pin == "OUT") {
      out_ = &bus.line(line).driver();
      out_->set(Level::Low);
    } else {
      throw std::invalid_argument("reference_pls has no pin " + pin);
    }
  }
  const bool a = a_ != nullptr && is_high(a_->level());
  const bool b = b_ != nullptr && is_high(b_->level());
  ab_state_ = static_cast<std::uint8_t>((a ? 2U : 0U) | (b ? 1U : 0U));
}

void ReferencePls::on_quadrature() {
  const bool a = a_ != nullptr && is_high(a_->level());
  const bool b = b_ != nullptr && is_high(b_->level());
  const auto next = static_cast<std::uint8_t>((a ? 2U : 0U) | (b ? 1U : 0U));
  count_ += kStep[static_cast<std::size_t>((ab_state_ << 2U) | next)];
  ab_state_ = next;
}

void ReferencePls::on_enable(const Edge& e) { en_changed_ = e.time; }

bool ReferencePls::enabled(Nanos now) const {
  if (en_ == nullptr) return true;
  // The filter holds the last accepted level until the line has been stable long enough;
  // with no history of an accepted level the output stays disabled.
  if (config_.variant == Variant::NoFilter) return is_high(en_->level());
  return now - en_changed_ >= config_.filter && is_high(en_->level());
}

void ReferencePls::scan() {
  const Nanos now = scheduler_.now();
  const std::int64_t seen = config_.variant == Variant::OffByOne ? count_ - 1 : count_;
  bool want = seen >= config_.on && seen < config_.off && enabled(now);
  if (config_.variant == Variant::StuckOff) want = false;
  if (want != decided_) {
    decided_ = want;
    Nanos delay = config_.delay;
    if (config_.variant == Variant::Late) delay += config_.scan;
    if (out_ != nullptr) {
      LineOutput* out = out_;
      const Level level = level_of(want);
      scheduler_.at(now + delay, [out, level] { out->set(level); });
    }
  }
  scheduler_.at(now + config_.scan, [this] { scan(); });
}

void ReferencePls::run_command() {
  const std::uint16_t command = out_words_[0] & 0x000FU;
  command_error_ = false;
  if (command == 1) {
    const auto on = static_cast<std::int16_t>(out_words_[1]);
    const auto off = static_cast<std::int16_t>(out_words_[2]);
    if (on >= off) {
      command_error_ = true;
      return;
    }
    config_.on = on;
    config_.off = off;
  } else if (command == 2) {
    count_ = static_cast<std::int16_t>(out_words_[1]);
  } else {
    command_error_ = true;
  }
}

void ReferencePls::host_write(std::size_t word, std::uint16_t value) {
  if (word >= kOutputWords) throw std::out_of_range("reference_pls: output word out of range");
  out_words_[word] = value;
  if (word != 0) return;
  const bool transmit = (value & 0x8000U) != 0;
  if (transmit && !transmit_) {
    // Acts at its next scan, as a scanned controller does.
    scheduler_.at(scheduler_.now() + config_.scan, [this] {
      if (!transmit_ || config_.variant == Variant::NoAck) return;
      run_command();
      acknowledge_ = true;
    });
  } else if (!transmit && transmit_) {
    scheduler_.at(scheduler_.now() + config_.scan, [this] { acknowledge_ = false; });
  }
  transmit_ = transmit;
}

std::uint16_t ReferencePls::host_read(std::size_t word) const {
  switch (word) {
  case 0:
    return static_cast<std::uint16_t>((acknowledge_ ? 0x8000U : 0U) | (command_error_ ? 0x0002U : 0U) |
                                      (decided_ ? 0x0001U : 0U));
  case 1:
    return low_word(count_);
  case 2:
    return low_word(config_.on);
  case 3:
    return low_word(config_.off);
  default:
    throw std::out_of_range("reference_pls: input word out of range");
  }
}

DutInfo reference_pls_info() {
  DutInfo info;
  info.name = "reference_pls";
  info.description = "reference limit switch: one output on between two setpoints (test double)";
  info.pins = {
      {"A", PinDirection::Input, "quadrature channel A"},
      {"B", PinDirection::Input, "quadrature channel B"},
      {"EN", PinDirection::Input, "output enable (filtered); unwired = enabled"},
      {"OUT", PinDirection::Output, "the limit switch output"},
  };
  // A test double with no manual: counts are the 16-bit host words' (-32768 .. 32767); a scan
  // of 1 us .. 100 ms (a 1 ns scan is 10^9 events per virtual second), delays 0 .. 1 s.
  const ParamRange count = between(-32'768.0, 32'767.0);
  info.params = {
      {"on", ParamKind::Integer, std::int64_t{100}, "count at which OUT turns on", count},
      {"off", ParamKind::Integer, std::int64_t{300}, "count at which OUT turns off", count},
      {"scan", ParamKind::Duration, Nanos{200'000}, "scan period", between(1_us, 100_ms)},
      {"delay", ParamKind::Duration, Nanos{50'000}, "throughput delay from scan to output pin",
       between(0_us, 1_s)},
      {"filter", ParamKind::Duration, Nanos{1'000'000}, "EN input filter time", between(0_us, 1_s)},
      {"preset", ParamKind::Integer, std::int64_t{0}, "count at power-up", count},
  };
  info.variants = {
      {"nominal", "as specified"},
      {"late", "every output change one scan late"},
      {"off-by-one", "compares the count one lower: edges one count late"},
      {"stuck-off", "OUT never turns on"},
      {"no-filter", "EN is not filtered"},
      {"no-ack", "never acknowledges a host command"},
  };
  info.host = HostInterface{ReferencePls::kOutputWords, ReferencePls::kInputWords, true, 15, 15};
  info.make = [](Scheduler& scheduler, const DutParams& params, std::string_view variant,
                 std::uint64_t seed) -> std::unique_ptr<Dut> {
    ReferencePls::Config c;
    c.on = params.integer("on");
    c.off = params.integer("off");
    c.scan = params.duration("scan");
    c.delay = params.duration("delay");
    c.filter = params.duration("filter");
    c.preset = params.integer("preset");
    if (c.scan <= Nanos{0}) throw std::invalid_argument("reference_pls: scan must be > 0");
    c.phase = phase_from_seed(seed, c.scan);
    if (variant == "nominal")
      c.variant = ReferencePls::Variant::Nominal;
    else if (variant == "late")
      c.variant = ReferencePls::Variant::Late;
    else if (variant == "off-by-one")
      c.variant = ReferencePls::Variant::OffByOne;
    else if (variant == "stuck-off")
      c.variant = ReferencePls::Variant::StuckOff;
    else if (variant == "no-filter")
      c.variant = ReferencePls::Variant::NoFilter;
    else if (variant == "no-ack")
      c.variant = ReferencePls::Variant::NoAck;
    else
      throw std::invalid_argument("reference_pls has no variant " + std::string(variant));
    return std::make_unique<ReferencePls>(scheduler, c);
  };
  return info;
}

} // namespace hilrig::duts
