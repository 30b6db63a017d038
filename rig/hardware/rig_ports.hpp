#pragma once
// What a hardware run talks to, behind narrow interfaces: the RT loop's output and input
// ports (core/rt_ports.hpp, indexed as the DrivePlan orders the lines), the host words and
// the resolver's CAN link. open_rig_ports() builds them from the rig config (libgpiod,
// SocketCAN, Modbus); a test builds them around a virtual DUT.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/can_frame.hpp"
#include "core/rt_ports.hpp"
#include "rig/campaign/host_sequence.hpp"
#include "rig/campaign/virtual_run.hpp"
#include "rig/hardware/drive_plan.hpp"

namespace hilrig::hardware {

// Frames the resolver's CAN interface lost during a run: overruns its controller reported
// in error frames (CAN_ERR_CRTL_RX_OVERFLOW / TX_OVERFLOW) and frames the kernel dropped from
// the rig's socket because its receive queue was full (SO_RXQ_OVFL). Any of them is a rig
// fault (docs/rig-config.md): the bus evidence of the run is incomplete.
struct CanOverruns {
  std::uint64_t controller_rx = 0;
  std::uint64_t controller_tx = 0;
  std::uint64_t socket_drops = 0;
  [[nodiscard]] std::uint64_t total() const { return controller_rx + controller_tx + socket_drops; }
};

// The interface the resolver angle stream goes out on. Both calls return "" when all is
// well, or the rig fault that stops the run ("CAN can0: bus-off").
class ResolverCan {
public:
  virtual ~ResolverCan() = default;
  [[nodiscard]] virtual std::string send(const CanFrame& frame) = 0;
  // Reads what the controller reported since the last call (error frames, bus state).
  [[nodiscard]] virtual std::string check() = 0;
  [[nodiscard]] virtual const std::string& bus() const = 0; // the name in can.log
  // What check() has counted so far.
  [[nodiscard]] virtual CanOverruns overruns() const = 0;
};

class RigPorts {
public:
  virtual ~RigPorts() = default;
  [[nodiscard]] virtual RtOutputPort& outputs() = 0;
  [[nodiscard]] virtual RtInputPort* inputs() = 0;       // nullptr: nothing to capture
  [[nodiscard]] virtual campaign::HostWords* host() = 0; // nullptr: no host link
  [[nodiscard]] virtual ResolverCan* resolver() = 0;     // nullptr: no resolver stream
  // The level of captured line i before the run, when the backend can read it.
  [[nodiscard]] virtual std::optional<Level> input_level(std::size_t /*i*/) { return std::nullopt; }
  // The run starts at this absolute CLOCK_MONOTONIC time; input edges are stamped on that clock.
  virtual void begin(Nanos /*start*/) {}
};

// Opens a run's ports: its lines placed on the rig, and what the run plays (for a harness).
using RigPortsFactory =
    std::function<std::unique_ptr<RigPorts>(const DrivePlan&, const campaign::RunInputs&)>;

// The real rig: GPIO lines through libgpiod (outputs bulk-requested per chip and settings),
// the host link through libmodbus, the resolver stream through SocketCAN. Throws (GpioError,
// HostLinkError, CanError) naming what could not be opened.
[[nodiscard]] std::unique_ptr<RigPorts> open_rig_ports(const RigConfig& config, const DrivePlan& plan,
                                                       const campaign::Scenario& scenario);

} // namespace hilrig::hardware
