// The ANS1's command blocks in its manual's words (docs/spec/ans1.md §5.3; manual seeds/000,
// Lnnn). Word 0 is the block number (bits 3..0) with the block's Apply bits; the rig adds
// Transmit. Positions are 0 .. 4095: FSC is at most CPC <= 4096 (L1797-L1840); a value at or
// past the programmed FSC is the board's Parameter Error 1001, not the campaign's.

#include <cstdint>
#include <optional>
#include <vector>

#include "rig/duts/device_programs.hpp"

namespace hilrig::duts {
namespace {

using Words = std::vector<std::uint16_t>;
using Opt = std::optional<std::int64_t>;
constexpr std::int64_t kMaxPosition = 4095; // FSC - 1 at FSC = CPC = 4096
constexpr std::int64_t kMaxMs = 32767;      // the manual's ms words (L1945-L1962, L2099-L2125)

// Words 0 .. the last one given: an Apply bit's word left out is 0 (ignored by the board).
Words with_words(std::uint16_t word0, const std::vector<Opt>& words) {
  Words out{word0};
  std::size_t last = 0;
  for (std::size_t i = 0; i < words.size(); ++i)
    if (words[i]) last = i + 1;
  for (std::size_t i = 0; i < last; ++i) out.push_back(word(words[i].value_or(0)));
  return out;
}

// CB0 with Clear Errors (bit 4): clears error codes 1001..1100 and a latched fault (L1713-L1721).
struct ClearErrors {};
Words clear_errors(const ClearErrors&) { return {bit(4)}; }

// CB2, Global Machine Configuration (L1791-L1840): word 1's bit parameters always (Apply w1,
// bit 7), CPC and FSC when given (bits 8, 9).
struct Configuration {
  std::int64_t sensor = 0; // 0 resolver, 1 encoder (QuadEnc)
  bool hold_outputs = false;
  bool slave = false;
  bool fault_latch = false;
  bool reverse = false;
  Opt cpc;
  Opt fsc;
};
Words configuration(const Configuration& c) {
  const auto w1 = static_cast<std::uint16_t>(bit(4, c.hold_outputs) | bit(3, c.sensor == 1) |
                                             bit(2, c.slave) | bit(1, c.fault_latch) | bit(0, c.reverse));
  const auto w0 =
      static_cast<std::uint16_t>(0x0002U | bit(7) | bit(8, c.cpc.has_value()) | bit(9, c.fsc.has_value()));
  return with_words(w0, {w1, c.cpc, c.fsc});
}

// CB3, one setpoint pair of an output (L1842-L1898): Apply pair k is bit 9 + k; pair k is
// words 4k .. 4k+3: From (on), To (off), OnStitch, OffStitch.
struct Setpoints {
  std::int64_t output = 1;
  std::int64_t pair = 1;
  std::int64_t on = 0;
  std::int64_t off = 0;
  std::int64_t on_stitch = 0;
  std::int64_t off_stitch = 0;
};
Words setpoints(const Setpoints& s) {
  Words w(static_cast<std::size_t>(4 * s.pair + 4), 0);
  w[0] = static_cast<std::uint16_t>(0x0003U | bit(static_cast<unsigned>(9 + s.pair)));
  w[1] = word(s.output);
  const auto k = static_cast<std::size_t>(4 * s.pair);
  w[k] = word(s.on);
  w[k + 1] = word(s.off);
  w[k + 2] = word(s.on_stitch);
  w[k + 3] = word(s.off_stitch);
  return w;
}

// CB5 bits 9:8 = 01, fixed-delay advances (L1945-L1951): word 2 Lead, word 3 Trail, ms.
struct FixedAdvance {
  std::int64_t output = 1;
  std::int64_t lead_ms = 0;
  std::int64_t trail_ms = 0;
};
Words fixed_advance(const FixedAdvance& a) {
  return {0x0105, word(a.output), word(a.lead_ms), word(a.trail_ms)};
}

// CB5 bits 9:8 = 10, variable-delay advances (L1945-L1951): word 2 Fixed (ms), word 3 VAT (us/RPM).
struct VariableAdvance {
  std::int64_t output = 1;
  std::int64_t fixed_ms = 0;
  std::int64_t vat = 0;
};
Words variable_advance(const VariableAdvance& a) {
  return {0x0205, word(a.output), word(a.fixed_ms), word(a.vat)};
}

// CB5 bits 11:10, a timed output (L1957-L1962): 01 Time-or-Position, 1x Time-Only; word 4 ms.
struct Timer {
  std::int64_t output = 1;
  std::int64_t timer = 0; // 0 time_or_position, 1 time_only
  std::int64_t ms = 0;
};
Words timer(const Timer& t) {
  return {static_cast<std::uint16_t>(0x0005U | bit(t.timer == 1 ? 11U : 10U)), word(t.output), 0, 0,
          word(t.ms)};
}

// CB8, the brake monitor (L2099-L2125): Apply word k is bit 7 + k, for each setting given.
struct BrakeMonitor {
  Opt input;
  Opt csc;
  Opt start_limit_ms;
  Opt start_output;
  Opt stop_limit_ms;
  Opt stop_output;
};
Words brake_monitor(const BrakeMonitor& b) {
  const std::vector<Opt> words{b.input,        b.csc,           b.start_limit_ms,
                               b.start_output, b.stop_limit_ms, b.stop_output};
  std::uint16_t w0 = 0x0008;
  for (unsigned k = 0; k < words.size(); ++k)
    w0 = static_cast<std::uint16_t>(w0 | bit(8 + k, words[k].has_value()));
  return with_words(w0, words);
}

// CB1 bit 8, the data attribute block the status words 1..19 return (L1723-L1789).
struct Data {
  std::int64_t attribute = 0;
  std::int64_t output = 1;
  std::int64_t input = 1;
};
Words data(const Data& d) { return {0x0101, word(d.attribute), word(d.output), word(d.input)}; }

} // namespace

std::vector<ProgramBlockInfo> ans1_programs() {
  return {
      program_block<ClearErrors>("clear_errors",
                                 "CB0 with Clear Errors: error codes and latched faults (L1713-L1721)", {},
                                 &clear_errors),
      program_block<Configuration>(
          "configuration", "CB2 Global Machine Configuration: sensor, bit parameters, CPC, FSC (L1791-L1840)",
          {
              {"sensor",
               &Configuration::sensor,
               "the position sensor (QuadEnc, w1 bit 3)",
               0,
               0,
               {"resolver", "encoder"},
               true},
              {"hold_outputs", &Configuration::hold_outputs,
               "HoldOuts (w1 bit 4): outputs hold on a transducer fault"},
              {"slave", &Configuration::slave, "SlaveMode (w1 bit 2)"},
              {"fault_latch", &Configuration::fault_latch,
               "XFltLatch (w1 bit 1): a resolver fault clears by itself"},
              {"reverse", &Configuration::reverse, "CntDir (w1 bit 0): counts up counter-clockwise"},
              {"cpc", &Configuration::cpc, "Counts per Cycle (w2, L1797)", 2, 4096},
              {"fsc", &Configuration::fsc, "Full Scale Count (w3, 1 .. CPC)", 1, 4096},
          },
          &configuration),
      program_block<Setpoints>(
          "setpoints", "CB3 one setpoint pair of an output: on (From) .. off (To), stitches (L1842-L1898)",
          {
              {"output", &Setpoints::output, "the output (w1)", 1, 16},
              {"pair", &Setpoints::pair, "which of the output's four pairs", 1, 4, {}, true},
              {"on", &Setpoints::on, "From: the output turns on here", 0, kMaxPosition},
              {"off", &Setpoints::off, "To: the output turns off here", 0, kMaxPosition},
              {"on_stitch", &Setpoints::on_stitch, "OnStitch (0: none)", 0, kMaxPosition, {}, true},
              {"off_stitch", &Setpoints::off_stitch, "OffStitch (0: none)", 0, kMaxPosition, {}, true},
          },
          &setpoints),
      program_block<FixedAdvance>(
          "fixed_advance", "CB5 fixed-delay advances of an output, ms (L1945-L1951)",
          {
              {"output", &FixedAdvance::output, "the output (w1)", 1, 16},
              {"lead_ms", &FixedAdvance::lead_ms, "Lead Advance Time (w2)", 0, kMaxMs, {}, true},
              {"trail_ms", &FixedAdvance::trail_ms, "Trail Advance Time (w3)", 0, kMaxMs, {}, true},
          },
          &fixed_advance),
      program_block<VariableAdvance>(
          "variable_advance", "CB5 variable-delay advances of an output (L1945-L1951, L917)",
          {
              {"output", &VariableAdvance::output, "the output (w1)", 1, 16},
              {"fixed_ms", &VariableAdvance::fixed_ms, "Fixed Advance Time, ms (w2)", 0, kMaxMs, {}, true},
              {"vat", &VariableAdvance::vat, "Variable Advance Time, us/RPM (w3)", 0, 9999, {}, true},
          },
          &variable_advance),
      program_block<Timer>("timer", "CB5 a timed output: Time-or-Position or Time-Only (L1957-L1962)",
                           {
                               {"output", &Timer::output, "the output (w1)", 1, 16},
                               {"timer",
                                &Timer::timer,
                                "the timer type (bits 11:10)",
                                0,
                                0,
                                {"time_or_position", "time_only"}},
                               {"ms", &Timer::ms, "the timer (w4, 0 disables it)", 0, kMaxMs},
                           },
                           &timer),
      program_block<BrakeMonitor>(
          "brake_monitor", "CB8 the brake monitor; each setting given is applied (L2099-L2125)",
          {
              {"input", &BrakeMonitor::input, "the brake input (w1, 0: off)", 0, 16},
              {"csc", &BrakeMonitor::csc, "Consecutive Stroke Count (w2)", 0, 255},
              {"start_limit_ms", &BrakeMonitor::start_limit_ms, "Start Time Limit (w3)", 0, kMaxMs},
              {"start_output", &BrakeMonitor::start_output, "Start Overrun Output (w4, 0: none)", 0, 16},
              {"stop_limit_ms", &BrakeMonitor::stop_limit_ms, "Stop Time Limit (w5)", 0, kMaxMs},
              {"stop_output", &BrakeMonitor::stop_output, "Stop Overrun Output (w6, 0: none)", 0, 16},
          },
          &brake_monitor),
      program_block<Data>(
          "data",
          "CB1 the data attribute block status words 1..19 return (0..8, 16..20; L1723-L1789, "
          "L2317)",
          {
              {"attribute", &Data::attribute, "the data attribute block (w1)", 0, 20},
              {"output", &Data::output, "the output it reports on (w2)", 1, 16, {}, true},
              {"input", &Data::input, "the input it reports on (w3)", 1, 16, {}, true},
          },
          &data),
  };
}

} // namespace hilrig::duts
