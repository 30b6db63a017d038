#pragma once
// The virtual bus: in-process digital lines, CAN buses, serial links and analog channels
// in the Scheduler's virtual time. Models and the rig meet here; it implements the same
// core interfaces (LineOutput, LineInput, CanPort, ByteLink, AnalogInput) as the real drivers.

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "core/analog.hpp"
#include "core/can_frame.hpp"
#include "core/line.hpp"
#include "core/scheduler.hpp"
#include "core/serial.hpp"
#include "core/trace.hpp"
#include "drivers/virtual/analog_channel.hpp"
#include "drivers/virtual/can_bus.hpp"
#include "drivers/virtual/digital_line.hpp"
#include "drivers/virtual/serial_link.hpp"

namespace hilrig::virt {

class VirtualBus {
public:
  // trace may be null: then nothing is recorded.
  explicit VirtualBus(Scheduler& scheduler, TraceRecorder* trace = nullptr);

  [[nodiscard]] Scheduler& scheduler() { return scheduler_; }

  // Each accessor creates the named thing on first use and returns the same one after.
  DigitalLine& line(std::string_view name, Level initial = Level::Low);
  // Every digital line, made now or later, powers up (DigitalLine::set_powering_up) until
  // this is called again with false: a run powers the bus up while it makes the board, so the
  // levels the board drives at power-up are where its lines start, not edges at time 0.
  void set_powering_up(bool on);
  CanBus& can(std::string_view name, const CanBitTiming& timing = {});
  SerialLink& serial(std::string_view name, const SerialFormat& format = {});
  AnalogChannel& analog(std::string_view name);

private:
  Scheduler& scheduler_;
  TraceRecorder* trace_;
  bool powering_up_ = false;
  std::map<std::string, std::unique_ptr<DigitalLine>, std::less<>> lines_;
  std::map<std::string, std::unique_ptr<CanBus>, std::less<>> cans_;
  std::map<std::string, std::unique_ptr<SerialLink>, std::less<>> serials_;
  std::map<std::string, std::unique_ptr<AnalogChannel>, std::less<>> analogs_;
};

} // namespace hilrig::virt
