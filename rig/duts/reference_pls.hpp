#pragma once
// The reference PLS: a small quadrature-counting limit switch that stands in for a real
// board so the whole campaign pipeline is tested end to end. It counts A/B in X4 from its
// power-up count (`preset`, 0 by default: it knows nothing of the shaft's absolute
// position until the host presets it), and every scan it turns its one output OUT on
// while on <= count < off (and EN, filtered, is high — EN unwired counts as high). A change decided at a scan
// reaches the pin a fixed throughput delay later. So a setpoint crossing shows on OUT after delay .. delay +
// scan.
//
// Host words (AMCI-style handshake: acts on output word 0 bit 15 going 0->1, answers
// with input word 0 bit 15):
//   output w0: bit 15 Transmit, bits 3..0 command: 1 = setpoints from w1 (on), w2 (off);
//              2 = preset the count to w1 (two's complement)
//   input  w0: bit 15 Acknowledge, bit 1 command error (on >= off or unknown command),
//              bit 0 OUT as decided by the last scan
//          w1: count (low 16 bits, two's complement), w2: on, w3: off
//
// Variants: nominal; late (each change one extra scan late); off-by-one (compares the
// count one lower, so edges come one count late going forward); stuck-off (OUT never
// turns on); no-filter (EN taken as is, no filter); no-ack (never raises Acknowledge).
// The scan phase (where its scan clock sits against rig time) is drawn from the run's seed.

#include <array>
#include <cstdint>
#include <string_view>

#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

class ReferencePls final : public Dut {
public:
  enum class Variant : std::uint8_t { Nominal, Late, OffByOne, StuckOff, NoFilter, NoAck };

  struct Config {
    std::int64_t on = 100;
    std::int64_t off = 300;
    Nanos scan{200'000};
    Nanos delay{50'000};
    Nanos filter{1'000'000}; // EN must be stable this long to be taken
    std::int64_t preset = 0; // the count at power-up (an incremental encoder starts anywhere)
    Variant variant = Variant::Nominal;
    Nanos phase{0}; // first scan at phase + scan: where the scan clock sits against rig time
  };

  ReferencePls(Scheduler& scheduler, Config config);

  void attach(virt::VirtualBus& bus,
              const std::map<std::string, std::string, std::less<>>& pin_to_line) override;
  void host_write(std::size_t word, std::uint16_t value) override;
  [[nodiscard]] std::uint16_t host_read(std::size_t word) const override;

  [[nodiscard]] std::int64_t count() const { return count_; }

  static constexpr std::size_t kOutputWords = 3;
  static constexpr std::size_t kInputWords = 4;

private:
  void on_quadrature();
  void on_enable(const Edge& e);
  void scan();
  void run_command();
  [[nodiscard]] bool enabled(Nanos now) const;

  Scheduler& scheduler_;
  Config config_;
  LineInput* a_ = nullptr;
  LineInput* b_ = nullptr;
  LineInput* en_ = nullptr;
  LineOutput* out_ = nullptr;
  std::uint8_t ab_state_ = 0; // (A << 1) | B
  std::int64_t count_ = 0;
  Nanos en_changed_{0};
  bool decided_ = false; // OUT as last decided by a scan
  bool transmit_ = false;
  bool acknowledge_ = false;
  bool command_error_ = false;
  std::array<std::uint16_t, kOutputWords> out_words_{};
};

// The registry entry (name "reference_pls").
[[nodiscard]] DutInfo reference_pls_info();

} // namespace hilrig::duts
