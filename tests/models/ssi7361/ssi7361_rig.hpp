#pragma once
// A bench for the virtual 7361, wired as the rig wires it: the module drives the clock line
// of a virtual bus and reads the data line; an SsiSlave on an SsiSlaveNode plays the
// transducer. Tests talk to the module only through these lines and its host words.
// Words are written as a PLC does (digest §5.3): %AQ first with TRMT = 0, then TRMT 0->1,
// read %I while ACK = 1, then TRMT 1->0.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/scheduler.hpp"
#include "drivers/virtual/virtual_bus.hpp"
#include "models/ssi7361/host_words.hpp"
#include "models/ssi7361/ssi7361.hpp"
#include "signals/ssi_frame.hpp"
#include "signals/ssi_slave.hpp"
#include "signals/ssi_slave_node.hpp"

namespace hilrig::models::ssi7361::test {

using namespace hilrig::literals;

// The status word a programming block that took returns.
constexpr std::uint16_t kAck = ibit::kAcknowledge;
// %R1 of the checkout, block A (M-02): Format, Scalars, PrstVal, RUT, PgmDir.
constexpr std::uint16_t kBlockA = 62;
static_assert(kBlockA ==
              (qbit::kFormat | qbit::kScalars | qbit::kPresetValue | qbit::kRut | qbit::kProgramDirection));

// %AQ1 as the examples' notation writes it: (clk500<<15) | (M<<8) | (neg<<7) | (gray<<6) | N.
constexpr std::uint16_t format_word(unsigned msb, unsigned bits, bool gray = false, bool negative = false,
                                    bool clock500 = false) {
  return static_cast<std::uint16_t>((clock500 ? 0x8000u : 0u) | (msb << 8) | (negative ? 0x80u : 0u) |
                                    (gray ? 0x40u : 0u) | bits);
}

// The %AQ words of one cycle (unused ones may stay 0).
struct Aq {
  std::uint16_t format = 0;
  std::uint16_t multiplier = 0;
  std::uint16_t divisor = 0;
  std::int32_t preset = 0;
  std::uint16_t rut = 0;
};

class Rig {
public:
  explicit Rig(Params params = {})
      : clock_line_(bus_.line("ssi7361.clock", Level::High)),
        data_line_(bus_.line("ssi7361.data", Level::High)),
        module_(std::make_unique<Ssi7361>(scheduler_, clock_line_.driver(), data_line_.reader(), params)) {}
  Rig(const Rig&) = delete;
  Rig& operator=(const Rig&) = delete;
  ~Rig() {
    module_.reset(); // before the node and slave it clocks
  }

  // Connects a transducer sending `format` frames of source(t) (latched at F1).
  void attach_sensor(signals::SsiFrameFormat format, std::function<std::uint32_t(Nanos)> source,
                     Nanos output_delay = Nanos{0}) {
    signals::SsiSlaveParams p;
    p.format = format;
    p.output_delay = output_delay;
    slave_.emplace(p, std::move(source));
    node_.emplace(scheduler_, *slave_, clock_line_.reader(), data_line_.driver());
  }
  // A transducer that sends the 25-bit word `word` as it is (stream bit 1 = its MSB).
  void attach_word_sensor(Nanos output_delay = Nanos{0}) {
    attach_sensor(
        signals::ssi7361_frame(1, 25), [this](Nanos) { return word; }, output_delay);
  }
  void set_sensor_faults(const signals::SsiSlaveFaults& f) { node_->set_faults(f); }

  // Sets what the word sensor sends and lets two frames pass, so the module has read it.
  void send(std::uint32_t w) {
    word = w;
    run_for(1_ms);
  }

  void run_for(Nanos d) { scheduler_.run_until(scheduler_.now() + d); }
  void run_until(Nanos t) { scheduler_.run_until(t); }
  [[nodiscard]] Nanos now() const { return scheduler_.now(); }

  // One Programming Cycle; returns %I as read while ACK is set (or after `wait` when the
  // module acknowledges late).
  std::uint16_t program(std::uint16_t q, const Aq& aq = {}, Nanos wait = Nanos{0}) {
    const auto preset = split_words(aq.preset);
    const std::uint16_t words[6] = {aq.format, aq.multiplier, aq.divisor, preset[0], preset[1], aq.rut};
    module_->write_command_words(1, words);
    module_->write_command(cmd::kQ, static_cast<std::uint16_t>(q & ~qbit::kTransmit));
    module_->write_command(cmd::kQ, static_cast<std::uint16_t>(q | qbit::kTransmit));
    if (wait > Nanos{0}) run_for(wait);
    const std::uint16_t i = status()[status::kI];
    module_->write_command(cmd::kQ, static_cast<std::uint16_t>(q & ~qbit::kTransmit));
    if (wait > Nanos{0}) run_for(wait);
    return i;
  }

  [[nodiscard]] StatusWords status() const { return module_->status_words(); }
  [[nodiscard]] std::int32_t dv() const {
    const auto w = status();
    return join_words(w[status::kDataLow], w[status::kDataHigh]);
  }
  [[nodiscard]] std::int32_t rate() const {
    const auto w = status();
    return join_words(w[status::kRateLow], w[status::kRateHigh]);
  }
  [[nodiscard]] std::uint32_t raw() const {
    const auto w = status();
    return (static_cast<std::uint32_t>(w[status::kRawHigh]) << 16) | w[status::kRawLow];
  }
  [[nodiscard]] std::uint16_t status_bits() const { return status()[status::kI]; }

  Ssi7361& module() { return *module_; }
  virt::DigitalLine& clock_line() { return clock_line_; }
  virt::DigitalLine& data_line() { return data_line_; }

  std::uint32_t word = 0; // what attach_word_sensor's transducer sends

private:
  Scheduler scheduler_;
  virt::VirtualBus bus_{scheduler_};
  virt::DigitalLine& clock_line_;
  virt::DigitalLine& data_line_;
  std::optional<signals::SsiSlave> slave_;
  std::optional<signals::SsiSlaveNode> node_;
  std::unique_ptr<Ssi7361> module_;
};

} // namespace hilrig::models::ssi7361::test
