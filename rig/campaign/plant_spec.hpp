#pragma once
// The campaign's [plant]: which physical model turns the encoder shaft, its SI parameters,
// its parameter changes in time (a worn brake from t), which board outputs act on it and
// the rig's own commands to it. docs/plants.md describes every key.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "models/plants/plant.hpp"
#include "models/plants/press.hpp"
#include "models/plants/rotary_axis.hpp"
#include "models/plants/stepper_load.hpp"
#include "rig/campaign/campaign_error.hpp"

namespace hilrig::campaign {

enum class PlantKind : std::uint8_t { Press, RotaryAxis, StepperLoad };

// The rig sets a plant input at a time (an operator dropping the valve, say).
struct PlantCommand {
  Nanos at{0};
  plants::PlantInput input = plants::PlantInput::Valve;
  Level level = Level::Low;
  SourcePos where;
};

struct PlantSpec {
  PlantKind kind = PlantKind::Press;
  Nanos step{100'000}; // the integrator's step
  plants::PressParams press;
  plants::PressStart press_start;
  std::vector<plants::ParamChange<plants::PressParams>> press_changes;
  plants::RotaryParams rotary;
  plants::RotaryStart rotary_start;
  std::vector<plants::ParamChange<plants::RotaryParams>> rotary_changes;
  plants::StepperParams stepper;
  std::vector<plants::ParamChange<plants::StepperParams>> stepper_changes;
  // Board outputs acting on the plant: rig line (a wire to a board output) -> input.
  std::map<std::string, plants::PlantInput, std::less<>> inputs;
  std::vector<PlantCommand> commands;
  // A rig line (to a board input) that mirrors the valve: high while energized (brake
  // released), low while de-energized (brake applied). "" when none.
  std::string valve_monitor;
  SourcePos where;
};

} // namespace hilrig::campaign
