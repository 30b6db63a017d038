#pragma once
// The far side of `hilrig serve`: a served board's pins on real kernel interfaces, so a rig
// drives and captures it as it would a board on the bench.
//   - digital pins on a gpio-sim chip's simulator side (far_lines.hpp), offsets from the
//     far config (far_config.hpp);
//   - the resolver stators from a resolver-emulator node (models/resolver_emulator) on a CAN
//     port, fed by the rig's ResolverAngle stream.
// It offers what ans1_pins.hpp's wire_pins_by_map asks of a bus: line(name), analog(name),
// with pin_map() naming every pin it carries. Real time: before the model's scheduler runs to
// t, poll(t) reads every board input and turns each change into an edge at t.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/analog.hpp"
#include "core/can_frame.hpp"
#include "core/scheduler.hpp"
#include "models/resolver_emulator/resolver_emulator.hpp"
#include "rig/far/far_config.hpp"
#include "rig/far/far_lines.hpp"

namespace hilrig::far {

using PinMap = std::map<std::string, std::string, std::less<>>;

// An analog pin fed by a Waveform (the node's SIN or COS).
class WaveformInput final : public AnalogInput {
public:
  explicit WaveformInput(Waveform waveform) : waveform_(std::move(waveform)) {}
  [[nodiscard]] double sample(Nanos t) const override { return waveform_(t); }

private:
  Waveform waveform_;
};

struct FarSideCounters {
  std::uint64_t polls = 0;
  std::uint64_t input_edges = 0;  // level changes read from the rig
  std::uint64_t output_edges = 0; // pulls written for the rig
};

class FarSide {
public:
  // chip_dir: the gpio-sim chip's sysfs directory (needed when the config has pins).
  // resolver_port: the node's CAN attachment (needed when the config has [resolver]).
  // Throws std::invalid_argument when one is missing, gpiosim::GpioSimError when a line's
  // file cannot be opened (when the model takes the pin).
  FarSide(Scheduler& scheduler, const FarConfig& config, std::string chip_dir, CanPort* resolver_port);
  FarSide(const FarSide&) = delete;
  FarSide& operator=(const FarSide&) = delete;
  ~FarSide();

  // Every pin this far side carries, each named by itself (the "bus line" is the pin).
  [[nodiscard]] const PinMap& pin_map() const { return pin_map_; }
  // Throws std::invalid_argument for a pin it does not carry.
  [[nodiscard]] FarLine& line(std::string_view pin);
  [[nodiscard]] AnalogInput& analog(std::string_view pin);

  // After the model took its pins: throws campaign::CampaignError at the config's entry of
  // a pin the model did not take (not a pin of `device`).
  void check_all_taken(std::string_view device) const;

  // Reads every board input; call before the scheduler runs to t.
  void poll(Nanos t);

  [[nodiscard]] FarSideCounters counters() const;
  [[nodiscard]] const models::resolver_emulator::ResolverEmulator* resolver() const { return node_.get(); }
  // One line: what the far side carries, for the serve command's banner.
  [[nodiscard]] std::string describe() const;

private:
  Scheduler& scheduler_;
  FarConfig config_;
  std::string chip_dir_;
  std::vector<std::unique_ptr<FarLine>> lines_;
  std::unique_ptr<models::resolver_emulator::ResolverEmulator> node_;
  std::unique_ptr<WaveformInput> sin_;
  std::unique_ptr<WaveformInput> cos_;
  PinMap pin_map_;
  std::uint64_t polls_ = 0;
};

} // namespace hilrig::far
