#include "drivers/virtual/virtual_bus.hpp"

namespace hilrig::virt {

VirtualBus::VirtualBus(Scheduler& scheduler, TraceRecorder* trace) : scheduler_(scheduler), trace_(trace) {}

DigitalLine& VirtualBus::line(std::string_view name, Level initial) {
  auto it = lines_.find(name);
  if (it == lines_.end()) {
    it = lines_
             .emplace(std::string(name),
                      std::make_unique<DigitalLine>(scheduler_, std::string(name), initial, trace_))
             .first;
    it->second->set_powering_up(powering_up_);
  }
  return *it->second;
}

void VirtualBus::set_powering_up(bool on) {
  powering_up_ = on;
  for (auto& entry : lines_) entry.second->set_powering_up(on);
}

CanBus& VirtualBus::can(std::string_view name, const CanBitTiming& timing) {
  auto it = cans_.find(name);
  if (it == cans_.end()) {
    it = cans_
             .emplace(std::string(name),
                      std::make_unique<CanBus>(scheduler_, std::string(name), timing, trace_))
             .first;
  }
  return *it->second;
}

SerialLink& VirtualBus::serial(std::string_view name, const SerialFormat& format) {
  auto it = serials_.find(name);
  if (it == serials_.end()) {
    it = serials_
             .emplace(std::string(name),
                      std::make_unique<SerialLink>(scheduler_, std::string(name), format, trace_))
             .first;
  }
  return *it->second;
}

AnalogChannel& VirtualBus::analog(std::string_view name) {
  auto it = analogs_.find(name);
  if (it == analogs_.end()) {
    it = analogs_.emplace(std::string(name), std::make_unique<AnalogChannel>(std::string(name))).first;
  }
  return *it->second;
}

} // namespace hilrig::virt
