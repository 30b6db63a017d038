#pragma once
// The devices `hilrig serve` can run: name -> a factory that builds the virtual model on a
// Scheduler and hands back the RegisterMap a Modbus server serves. To serve another model,
// add one entry to the table in serve_devices.cpp (and its library to serve.cmake).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/register_map.hpp"
#include "core/scheduler.hpp"
#include "drivers/modbus/pdu_handler.hpp"
#include "rig/cli/serve_controls.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::far {
class FarSide;
} // namespace hilrig::far

namespace hilrig::cli {

// Device-specific knobs from the command line; a factory reads the ones it knows.
struct ServeModelOptions {
  std::string fault = "none"; // fault variant name; "none" (or the model's nominal name) = as specified
  bool m12 = false;           // smd23e: an M12 unit
  bool no_encoder = false;    // smd23e: no internal encoder
  // ans1: the master scan period (the model's default 10 us when empty). A host slower than
  // the board (QEMU's emulated CPU) keeps real time with a longer one.
  std::optional<Nanos> scan_period;
  // Every [MODEL] parameter of the device's campaign adapter (defaults filled in, `--param`
  // overrides): pls2700, amci4501 and ssi7361 build their model from it.
  duts::DutParams params;
  bool params_given = false; // a --param was written (refused by devices that do not take them)
  // pls2700: the built-in transducer on every channel's stators, "constant:<rpm>rpm"; empty =
  // no stators (a transducer fault until a far side drives them).
  std::string motion;
};

// A built model: `keep` owns the model (and whatever it needs); `registers` is its host map.
struct ServedModel {
  std::shared_ptr<void> keep;
  RegisterMap* registers = nullptr;
  // Wires the model's pins to a far side (rig/far): empty when the model has no pins to offer.
  std::function<void(far::FarSide&)> attach_far;
  // The rig's controls of the board (serve_controls.hpp): its supply, its Program switch.
  BoardControls controls;
};

// Where the device's host words sit: command (output) word k is holding register
// command_base + k, status (input) word k is input register status_base + k. What a host
// (e.g. the campaign executive driving a ModbusClient) needs to address the words.
struct HostWordMap {
  std::uint16_t command_base = 0;
  std::uint16_t command_words = 0;
  std::uint16_t status_base = 0;
  std::uint16_t status_words = 0;
};

struct ServedDevice {
  std::string_view name;
  std::string_view description; // one line: what is served, where
  std::string_view faults;      // the fault variant names it accepts, for help texts
  HostWordMap words;
  // What the read half of FC 23 answers (pdu_handler.hpp): the protocol's AfterWrite unless
  // the device's manual documents otherwise.
  drivers::modbus::Fc23Read fc23_read = drivers::modbus::Fc23Read::AfterWrite;
  // Builds the model on the scheduler; throws std::invalid_argument for an unknown fault.
  std::function<ServedModel(Scheduler&, const ServeModelOptions&)> build;
};

[[nodiscard]] const std::vector<ServedDevice>& served_devices();
[[nodiscard]] const ServedDevice* find_served_device(std::string_view name); // nullptr: unknown
[[nodiscard]] std::string served_device_names();                             // "ans1, smd23e"

} // namespace hilrig::cli
