#include "rig/cli/serve_devices.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "drivers/virtual/virtual_bus.hpp"
#include "models/amci4501/amci4501.hpp"
#include "models/amci4501/registers.hpp"
#include "models/ans1/ans1.hpp"
#include "models/ans1/ans1_register_map.hpp"
#include "models/ans1/variants.hpp"
#include "models/pls2700/pls2700.hpp"
#include "models/pls2700/register_map.hpp"
#include "models/smd23e/smd23e.hpp"
#include "models/ssi7361/registers.hpp"
#include "models/ssi7361/ssi7361.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/duts/amci4501_dut.hpp"
#include "rig/duts/ans1_adapter.hpp"
#include "rig/duts/pls2700_dut.hpp"
#include "rig/duts/smd23e_dut.hpp"
#include "rig/duts/ssi7361_dut.hpp"
#include "rig/far/far_side.hpp"
#include "signals/resolver.hpp"

namespace hilrig::cli {

namespace {

// "none" is every model's as-specified variant; the models call it "nominal".
std::string_view nominal_if_none(const std::string& fault) {
  return fault == "none" ? std::string_view("nominal") : std::string_view(fault);
}

// Names the choices: a person who typed a fault wrong needs the list, not a second command.
[[noreturn]] void unknown_fault(std::string_view device, const std::string& fault) {
  const ServedDevice* d = find_served_device(device);
  throw std::invalid_argument("unknown fault variant '" + fault + "' for " + std::string(device) +
                              (d != nullptr ? " (one of: " + std::string(d->faults) + ")" : std::string()));
}

ServedModel build_smd23e(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto fault = models::smd23e::fault_from_name(o.fault);
  if (!fault) {
    unknown_fault("smd23e", o.fault);
  }
  // Every [MODEL] choice by its campaign name (rig/duts/smd23e_dut.cpp); --m12 and
  // --no-encoder are shorthands that win over them.
  models::smd23e::Params params = o.params_given ? duts::smd23e_params(o.params) : models::smd23e::Params{};
  params.fault = *fault;
  params.m12 = params.m12 || o.m12;
  params.has_encoder = params.has_encoder && !o.no_encoder;
  auto device = std::make_shared<models::smd23e::Smd23e>(scheduler, params);
  RegisterMap* map = device.get();
  BoardControls controls;
  controls.power = [d = device.get()](bool on) { on ? d->power_on() : d->power_off(); };
  return {std::move(device), map, {}, std::move(controls)};
}

// The ANS1 with no pins attached: no resolver signals (so Resolver Fault is set until a rig
// drives them), inputs off. Its host words are fully served. A far side gives it the pins
// its config names (encoder, inputs, outputs, stators); the rest stay unwired.
ServedModel build_ans1(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto variant = models::ans1::variant_from_name(nominal_if_none(o.fault));
  if (!variant) {
    unknown_fault("ans1", o.fault);
  }
  struct Served {
    Served(Scheduler& s, const models::ans1::Params& p, models::ans1::Variant v)
        : device(s, p, v), map(device) {}
    models::ans1::Ans1 device;
    models::ans1::Ans1RegisterMap map;
  };
  // Every [MODEL] choice by its campaign name (rig/duts/ans1_adapter.cpp); --scan wins.
  models::ans1::Params params = o.params_given ? duts::ans1_params(o.params) : models::ans1::Params{};
  if (o.scan_period) {
    params.master_scan_period = *o.scan_period;
  }
  auto served = std::make_shared<Served>(scheduler, params, *variant);
  RegisterMap* map = &served->map;
  auto attach = [device = &served->device](far::FarSide& far) {
    device->attach(models::ans1::wire_pins_by_map(far, far.pin_map()));
  };
  BoardControls controls;
  controls.power = [d = &served->device](bool on) { on ? d->power_on() : d->power_off(); };
  return {std::move(served), map, attach, std::move(controls)};
}

// The SSI 7361 with its clock and data lines on a private virtual bus and no encoder on them
// (undriven DATA reads 1, L2178). The host words (%Q/%AQ, %I/%AI) are fully served.
ServedModel build_ssi7361(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto variant = models::ssi7361::variant_from_string(nominal_if_none(o.fault));
  if (!variant) {
    unknown_fault("ssi7361", o.fault);
  }
  struct Served {
    Served(Scheduler& s, const models::ssi7361::Params& p)
        : bus(s), module(s, bus.line("ssi.clock", Level::High).driver(),
                         bus.line("ssi.data", Level::High).reader(), p),
          map(module) {}
    virt::VirtualBus bus;
    models::ssi7361::Ssi7361 module;
    models::ssi7361::Ssi7361Registers map;
  };
  models::ssi7361::Params params = duts::ssi7361_params(o.params);
  params.variant = *variant;
  auto served = std::make_shared<Served>(scheduler, params);
  RegisterMap* map = &served->map;
  BoardControls controls;
  controls.power = [d = &served->module](bool on) { on ? d->power_on() : d->power_off(); };
  return {std::move(served), map, {}, std::move(controls)};
}

// The 4501 with its encoder, Start, Latch and Cycle Output lines on a private virtual bus,
// all idle. The SLC words (O:s.0..7, I:s.0..7) are fully served.
ServedModel build_amci4501(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto variant = models::amci4501::variant_from_string(nominal_if_none(o.fault));
  if (!variant) {
    unknown_fault("amci4501", o.fault);
  }
  struct Served {
    Served(Scheduler& s, const models::amci4501::Params& p)
        : bus(s),
          module(s,
                 {bus.line("4501.a").reader(), bus.line("4501.b").reader(), bus.line("4501.start").reader(),
                  bus.line("4501.latch").reader(), bus.line("4501.cycle").driver()},
                 p),
          map(module) {}
    virt::VirtualBus bus;
    models::amci4501::Amci4501 module;
    models::amci4501::Amci4501Registers map;
  };
  models::amci4501::Params params = duts::amci4501_params(o.params);
  params.variant = *variant;
  auto served = std::make_shared<Served>(scheduler, params);
  RegisterMap* map = &served->map;
  BoardControls controls;
  controls.power = [d = &served->module](bool on) { on ? d->power_on() : d->power_off(); };
  return {std::move(served), map, {}, std::move(controls)};
}

// "constant:<rpm>rpm" (e.g. "constant:300rpm", "constant:-12.5rpm"): the transducer's speed.
double constant_rpm(const std::string& motion) {
  constexpr std::string_view kPrefix = "constant:";
  constexpr std::string_view kUnit = "rpm";
  const std::string_view m(motion);
  double rpm = 0.0;
  if (m.starts_with(kPrefix) && m.ends_with(kUnit) && m.size() > kPrefix.size() + kUnit.size()) {
    const char* first = m.data() + kPrefix.size();
    const char* last = m.data() + m.size() - kUnit.size();
    const auto [end, ec] = std::from_chars(first, last, rpm);
    if (ec == std::errc() && end == last && std::isfinite(rpm)) {
      // The boards' speed word, as a campaign's speed_rpm is bounded.
      if (std::abs(rpm) > campaign::limits::kMaxRpm)
        throw std::invalid_argument(fmt::format("--motion {0}: a speed -{1} .. {1} rpm (got {2} rpm)", motion,
                                                campaign::limits::kMaxRpm, rpm));
      return rpm;
    }
  }
  throw std::invalid_argument("--motion " + motion + ": expected constant:<rpm>rpm, e.g. constant:300rpm");
}

// A Series 2700 module (`--param model=`, the adapter's default 2742) on a private virtual bus.
// Without a motion its stators are open, so it reports a transducer fault (8000h position
// words); with one, a resolver turning at that speed drives every channel's stators (one
// transducer jumpered into both channels of a 2-channel module, R-18-8), locked to the
// module's own reference, so a host can program it and watch positions, tach and outputs.
ServedModel build_pls2700(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto fault = models::pls2700::fault_from_name(nominal_if_none(o.fault));
  if (!fault) {
    unknown_fault("pls2700", o.fault);
  }
  namespace p = models::pls2700;
  struct Served {
    Served(Scheduler& s, p::ModelVariant model, const p::Params& params, p::Fault f)
        : bus(s), module(s, p::wire_pins(bus, "pls."), model, params, f), map(module) {}
    virt::VirtualBus bus;
    p::Pls2700 module;
    p::Pls2700Registers map;
    std::optional<signals::Resolver> transducer;
  };
  auto served = std::make_shared<Served>(scheduler, duts::pls2700_model(o.params),
                                         duts::pls2700_params(o.params), *fault);
  if (!o.motion.empty()) {
    const double rpm = constant_rpm(o.motion);
    signals::Resolver& r = served->transducer.emplace(served->module.excitation().resolver_params(),
                                                      signals::angle_at_constant_speed(0.0, rpm / 60.0));
    for (int ch = 1; ch <= 2; ++ch) {
      served->bus.analog("pls." + p::sin_pin_name(ch)).set_waveform(r.sin_waveform());
      served->bus.analog("pls." + p::cos_pin_name(ch)).set_waveform(r.cos_waveform());
    }
  }
  RegisterMap* map = &served->map;
  BoardControls controls;
  p::Pls2700* module = &served->module;
  controls.power = [module](bool on) { on ? module->power_on() : module->power_off(); };
  controls.set_program_switch = [module](bool program) { module->set_program_switch(program); };
  controls.program_switch = [module] { return module->program_switch(); };
  controls.clear_last_pair = [module](int output) {
    (void)module->keyboard_delete_pair(
        output, module->setup().outputs[static_cast<std::size_t>(output - 1)].pair_count);
  };
  controls.outputs = p::kOutputCount;
  return {std::move(served), map, {}, std::move(controls)};
}

template <typename Names> std::string names_of(const Names& variants) {
  std::string names = "none";
  for (const auto& v : variants) {
    names += ", " + std::string(v.name);
  }
  return names;
}

} // namespace

const std::vector<ServedDevice>& served_devices() {
  static const std::string ans1_faults = names_of(models::ans1::kVariantNames);
  static const std::string amci4501_faults = names_of(models::amci4501::kVariantNames);
  static const std::string ssi7361_faults = names_of(models::ssi7361::kVariantNames);
  static const std::string pls2700_faults = names_of(models::pls2700::kFaultNames);
  static const std::vector<ServedDevice> devices{
      {"amci4501",
       "AMCI 4501 registration: input words I:s.0-7 at input registers 0-7, O:s.0-7 at holding 0-7",
       amci4501_faults,
       {0, 8, 0, 8},
       drivers::modbus::Fc23Read::AfterWrite,
       build_amci4501},
      {"ans1",
       "ANS1 limit switch: status words at input registers 0-19, command words at holding 1024-1043",
       ans1_faults,
       {1024, 20, 0, 20},
       drivers::modbus::Fc23Read::AfterWrite,
       build_ans1},
      {"pls2700",
       "Series 2700 limit switch (--param model=2731 .. 2742-18, default 2742; --motion constant:<rpm>rpm "
       "turns a built-in transducer): BTR at input registers 0-4 (1-channel modules 0-2), BTW at holding "
       "0-63 (FC16 at 0 = one BTW), error byte at holding 64",
       pls2700_faults,
       {0, 65, 0, 5},
       drivers::modbus::Fc23Read::AfterWrite,
       build_pls2700},
      {"smd23e",
       "SMD23E stepper: input registers 0-9, output words at holding registers 1024-1033",
       "none, wrong-acceleration, lost-steps, ignored-limit, late-stop",
       {1024, 10, 0, 10},
       // "the data read with that command will not contain the response to the new
       // configuration data. The response to the new data will be sent with the next data
       // read" (its manual, L2076).
       drivers::modbus::Fc23Read::ResponseFromBeforeWrite,
       build_smd23e},
      {"ssi7361",
       "AMCI 7361 SSI interface: %I, %AI1-6 at input registers 0-6, %Q, %AQ1-6 at holding 0-6",
       ssi7361_faults,
       {0, 7, 0, 7},
       drivers::modbus::Fc23Read::AfterWrite,
       build_ssi7361},
  };
  return devices;
}

const ServedDevice* find_served_device(std::string_view name) {
  for (const ServedDevice& d : served_devices()) {
    if (d.name == name) {
      return &d;
    }
  }
  return nullptr;
}

std::string served_device_names() {
  std::string names;
  for (const ServedDevice& d : served_devices()) {
    names += (names.empty() ? "" : ", ") + std::string(d.name);
  }
  return names;
}

} // namespace hilrig::cli
