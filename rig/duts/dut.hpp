#pragma once
// A DUT adapter: what the rig needs of any board, real or virtual. Pins by name, attach
// to the virtual bus by the campaign's wiring, the host's command/status words, and
// variants (models that are wrong on purpose) by name. Narrow on purpose: a device's
// own behaviour lives in its model, not here.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/scheduler.hpp"
#include "core/time.hpp"

namespace hilrig::signals {
class QuadratureWaveform;
}

namespace hilrig::virt {
class VirtualBus;
}

namespace hilrig::duts {

// Direction as the board sees it: the rig drives a board's Input, captures its Output.
enum class PinDirection : std::uint8_t { Input, Output };

struct PinInfo {
  std::string name;
  PinDirection direction = PinDirection::Input;
  std::string description;
  bool analog = false; // wired to an analog channel (resolver stators), not a digital line
};

enum class ParamKind : std::uint8_t { Integer, Number, Duration, Boolean, Text };
[[nodiscard]] const char* to_string(ParamKind kind);

// A parameter's value, already of its declared kind (Duration is Nanos).
using ParamValue = std::variant<std::int64_t, double, Nanos, bool, std::string>;

// The values a parameter may take: a closed interval for integers, numbers and durations
// (durations in ns), or the words a text parameter accepts. A campaign outside it is bad
// input. Each device cites, beside its bounds, the manual line or the rig limit behind them.
struct ParamRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices; // text parameters
};
[[nodiscard]] ParamRange between(double min, double max);
[[nodiscard]] ParamRange between(Nanos min, Nanos max);
[[nodiscard]] ParamRange one_of(std::vector<std::string> choices);
// Whether the value lies in the range (booleans always do).
[[nodiscard]] bool in_range(const ParamRange& range, const ParamValue& value);

struct ParamInfo {
  std::string name;
  ParamKind kind = ParamKind::Integer;
  ParamValue default_value;
  std::string description;
  ParamRange range;
};

// Values each in its parameter's range that do not go together (the Series 2700's reference
// frequency against its module's update period): bad input, refused before anything runs.
struct ParamConflict {
  std::vector<std::string> keys; // the parameters in conflict; an error points at the first one given
  std::string expected;          // what they must be
};

struct VariantInfo {
  std::string name;
  std::string description;
};

// Where a device fault ([[device_fault]]) is made. A board's own fault (an EEPROM error, an
// over-temperature) is raised in its model; a resolver fault is made by the rig on the stator
// signals it synthesizes, so the board detects it from the signal as a real board does.
enum class FaultSite : std::uint8_t {
  Board,       // the model: Dut::device_fault(index, active)
  OpenSin,     // the rig's SIN stator at amplitude 0: an open coil
  OpenCos,     // the rig's COS stator at amplitude 0: an open coil
  OpenStators, // both stators at amplitude 0: the transducer lost (cable off)
  StatorRatio, // both stators at the entry's `ratio` times the reference
};

// A fault the board's manual describes, started (and cleared) at times in a campaign.
struct DeviceFaultInfo {
  std::string name;        // as a campaign names it: fault = "eeprom_error"
  std::string description; // what the board does, per its manual (`hilrig list`)
  FaultSite site = FaultSite::Board;
  // `until` ends the condition (the board may keep it latched). False: the condition never
  // ends by itself, only the board's documented remedy clears it (the 7361's E2CLR).
  bool clears = true;
};

// A front-panel action the rig takes on a virtual board ([[panel]]): a switch set or a key
// pressed, as a person at the board would (the Series 2700's Program switch, its CLEAR key).
struct PanelActionInfo {
  std::string name;        // as a campaign names it: action = "program_mode"
  std::string description; // what the board does, per its manual (`hilrig list`)
};

class DutParams;

// The host's word interface (EtherNet/IP or Modbus registers on a real board).
struct HostInterface {
  std::size_t output_words = 0; // host -> board (command words)
  std::size_t input_words = 0;  // board -> host (status and data words)
  // The AMCI handshake: the board acts on Transmit (output word 0, this bit) going 0->1
  // and answers with Acknowledge (input word 0, this bit).
  bool handshake = true;
  unsigned transmit_bit = 15;
  unsigned acknowledge_bit = 15;
  // Nonzero: output word 0 sends a block transfer whose length it gives, 0 .. this (the
  // Series 2700's BTW, 0 meaning all 64 words, L1269); a larger word 0 is bad input.
  std::size_t block_length_max = 0;
  // Why input word `word` does not exist on a board of these parameters ("" when it does): a
  // word only some of a device's models have (the Series 2700's single-transfer word, the
  // 2731-04's only). Unset: every word below input_words exists. A campaign reading an absent
  // word is bad input, as `hilrig serve` answers it with Illegal Data Address.
  std::function<std::string(const DutParams&, std::size_t word)> input_absent{};
};

// Every parameter of a DUT with its value (the campaign's, or the default).
class DutParams {
public:
  DutParams() = default;
  explicit DutParams(std::map<std::string, ParamValue, std::less<>> values) : values_(std::move(values)) {}
  void set(std::string name, ParamValue value) { values_[std::move(name)] = std::move(value); }
  [[nodiscard]] std::int64_t integer(std::string_view name) const;
  [[nodiscard]] double number(std::string_view name) const;
  [[nodiscard]] Nanos duration(std::string_view name) const;
  [[nodiscard]] bool boolean(std::string_view name) const;
  [[nodiscard]] const std::string& text(std::string_view name) const;
  [[nodiscard]] const std::map<std::string, ParamValue, std::less<>>& values() const { return values_; }

private:
  [[nodiscard]] const ParamValue& at(std::string_view name) const;
  std::map<std::string, ParamValue, std::less<>> values_;
};

class Dut {
public:
  virtual ~Dut() = default;
  // Connects pins to bus lines: pin name -> bus line name, for the wired pins only.
  // Inputs become readers of their line; outputs become its driver; analog pins read the
  // bus's analog channel of that name.
  virtual void attach(virt::VirtualBus& bus,
                      const std::map<std::string, std::string, std::less<>>& pin_to_line) = 0;
  // The host writes one output word / reads one input word, at the scheduler's now.
  virtual void host_write(std::size_t word, std::uint16_t value) = 0;
  [[nodiscard]] virtual std::uint16_t host_read(std::size_t word) const = 0;
  // A board fault (DutInfo::faults[fault], site Board) starts (active) or its condition ends,
  // at the scheduler's now. The parser lets a campaign name only the faults a DUT declares.
  virtual void device_fault(std::size_t fault, bool active) {
    (void)active;
    throw std::logic_error("this DUT has no board fault " + std::to_string(fault));
  }
  // Its supply goes off (on = false) or comes back ([[power_cycle]]), at the scheduler's now.
  // The model keeps what its manual says survives power loss and starts again as at power-up.
  // The parser lets a campaign power-cycle only a DUT whose DutInfo::power_cycle says what it does.
  virtual void power(bool on) {
    (void)on;
    throw std::logic_error("this DUT has no power cycle");
  }
  // A front-panel action (DutInfo::panel[action]), at the scheduler's now.
  virtual void panel(std::size_t action) {
    throw std::logic_error("this DUT has no front-panel action " + std::to_string(action));
  }
  // Scan every period: the oracle of a model that skips the scans that change nothing
  // (docs/virtual-time.md; `hilrig run --exact-scan`). Called before the run starts; a model
  // that never skips has nothing to do.
  virtual void scan_every_period() {}
  // The rig's encoder lines a_line and b_line (bus line names) carry exactly `waveform`: no
  // fault or delay changes their edges. A model that only samples the count may ask the
  // waveform instead of taking every edge (docs/virtual-time.md, "Lines carry waveforms"); the
  // lines still carry every edge for anything else that reads them. Called before attach()
  // (and after scan_every_period()); the waveform outlives the DUT.
  virtual void sample_encoder(const std::string& a_line, const std::string& b_line,
                              signals::QuadratureWaveform& waveform) {
    (void)a_line;
    (void)b_line;
    (void)waveform;
  }
};

// seed: the run's seed, for what a real board leaves to chance (e.g. its scan phase).
using DutFactory = std::function<std::unique_ptr<Dut>(Scheduler&, const DutParams&, std::string_view variant,
                                                      std::uint64_t seed)>;

// What a campaign and `hilrig list` know of a device, and how to make its virtual model.
struct DutInfo {
  std::string name; // as a campaign names it: [dut] model = "reference_pls"
  std::string description;
  std::vector<PinInfo> pins;
  std::vector<ParamInfo> params;
  // The rules across parameters, for values each in range (unset: none): a campaign's
  // [dut.params] and `hilrig serve --param` are refused with what it returns.
  std::function<std::optional<ParamConflict>(const DutParams&)> conflict{};
  std::vector<VariantInfo> variants;   // "nominal" first
  std::vector<DeviceFaultInfo> faults; // [[device_fault]] fault = ...
  // What a power cycle ([[power_cycle]]) does to the board, per its manual (`hilrig list`).
  // Empty: the model has no power cycle, and a campaign asking for one is bad input.
  std::string power_cycle;
  std::vector<PanelActionInfo> panel; // [[panel]] action = ...
  HostInterface host;
  DutFactory make;

  [[nodiscard]] const PinInfo* pin(std::string_view pin_name) const;
  [[nodiscard]] const ParamInfo* param(std::string_view param_name) const;
  [[nodiscard]] bool has_variant(std::string_view variant) const;
  // The index of a device fault in `faults`, by name.
  [[nodiscard]] std::optional<std::size_t> fault_index(std::string_view fault_name) const;
  // The index of a front-panel action in `panel`, by name.
  [[nodiscard]] std::optional<std::size_t> panel_index(std::string_view action_name) const;
  // Defaults for every parameter, overridden by the given values.
  [[nodiscard]] DutParams with_defaults(const std::map<std::string, ParamValue, std::less<>>& given) const;
  // What `conflict` says of the given values over the defaults (nullopt when they go together
  // or there is no rule), its keys reordered so the first is the one to point at: the rule's
  // first key that `given` holds (a default is nowhere in the campaign), else its first.
  [[nodiscard]] std::optional<ParamConflict>
  params_conflict(const std::map<std::string, ParamValue, std::less<>>& given) const;
};

// Every DUT this build can simulate, in name order.
[[nodiscard]] const std::vector<DutInfo>& dut_registry();
[[nodiscard]] const DutInfo* find_dut(std::string_view name);

} // namespace hilrig::duts
