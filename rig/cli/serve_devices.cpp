#include "rig/cli/serve_devices.hpp"

#include <stdexcept>

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
#include "rig/far/far_side.hpp"

namespace hilrig::cli {

namespace {

// "none" is every model's as-specified variant; the models call it "nominal".
std::string_view nominal_if_none(const std::string& fault) {
  return fault == "none" ? std::string_view("nominal") : std::string_view(fault);
}

[[noreturn]] void unknown_fault(std::string_view device, const std::string& fault) {
  throw std::invalid_argument("unknown fault variant '" + fault + "' for " + std::string(device));
}

ServedModel build_smd23e(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto fault = models::smd23e::fault_from_name(o.fault);
  if (!fault) {
    unknown_fault("smd23e", o.fault);
  }
  models::smd23e::Params params;
  params.fault = *fault;
  params.m12 = o.m12;
  params.has_encoder = !o.no_encoder;
  auto device = std::make_shared<models::smd23e::Smd23e>(scheduler, params);
  RegisterMap* map = device.get();
  return {std::move(device), map, {}};
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
  models::ans1::Params params;
  if (o.scan_period) {
    params.master_scan_period = *o.scan_period;
  }
  auto served = std::make_shared<Served>(scheduler, params, *variant);
  RegisterMap* map = &served->map;
  auto attach = [device = &served->device](far::FarSide& far) {
    device->attach(models::ans1::wire_pins_by_map(far, far.pin_map()));
  };
  return {std::move(served), map, attach};
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
  models::ssi7361::Params params;
  params.variant = *variant;
  auto served = std::make_shared<Served>(scheduler, params);
  RegisterMap* map = &served->map;
  return {std::move(served), map, {}};
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
  models::amci4501::Params params;
  params.variant = *variant;
  auto served = std::make_shared<Served>(scheduler, params);
  RegisterMap* map = &served->map;
  return {std::move(served), map, {}};
}

// A Series 2731 (the single-channel standard module) with no stators attached, so it reports
// a transducer fault (8000h position words) until the host looks; its BTW/BTR words are served.
ServedModel build_pls2700(Scheduler& scheduler, const ServeModelOptions& o) {
  const auto fault = models::pls2700::fault_from_name(nominal_if_none(o.fault));
  if (!fault) {
    unknown_fault("pls2700", o.fault);
  }
  struct Served {
    Served(Scheduler& s, models::pls2700::Fault f)
        : module(s, models::pls2700::ModelVariant::M2731, {}, f), map(module) {}
    models::pls2700::Pls2700 module;
    models::pls2700::Pls2700Registers map;
  };
  auto served = std::make_shared<Served>(scheduler, *fault);
  RegisterMap* map = &served->map;
  return {std::move(served), map, {}};
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
       build_amci4501},
      {"ans1",
       "ANS1 limit switch: status words at input registers 0-19, command words at holding 1024-1043",
       ans1_faults,
       {1024, 20, 0, 20},
       build_ans1},
      {"pls2700",
       "Series 2731 limit switch: BTR at input registers 0-2, BTW at holding 0-63 (FC16 at 0 = one BTW), "
       "error byte at holding 64",
       pls2700_faults,
       {0, 65, 0, 3},
       build_pls2700},
      {"smd23e",
       "SMD23E stepper: input registers 0-9, output words at holding registers 1024-1033",
       "none, wrong-acceleration, lost-steps, ignored-limit, late-stop",
       {1024, 10, 0, 10},
       build_smd23e},
      {"ssi7361",
       "AMCI 7361 SSI interface: %I, %AI1-6 at input registers 0-6, %Q, %AQ1-6 at holding 0-6",
       ssi7361_faults,
       {0, 7, 0, 7},
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
