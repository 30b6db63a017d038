#pragma once
// The rig's host link: how a run's host actions (HostSequence) reach the board's command and
// status words. In process (the default) they call the DUT adapter directly; over Modbus RTU
// (modbus_host_link.hpp) the same words travel as register transactions on a serial line, a
// pty pair for a virtual DUT. Either way a word access happens at the scheduler's now, with
// virtual time standing still until it has finished, so the results do not depend on the link.

#include <functional>
#include <memory>
#include <string_view>

#include "rig/campaign/host_sequence.hpp"

namespace hilrig::duts {
class Dut;
struct DutInfo;
} // namespace hilrig::duts

namespace hilrig::campaign {

// Makes a run's link to its DUT. Called once per run that has host actions, on the thread
// that runs the simulation; the link is destroyed on that thread, before the DUT. A link's
// write/read throw on a failure of the link itself (hostlink::HostLinkError for Modbus).
using HostLinkFactory = std::function<std::unique_ptr<HostWords>(duts::Dut& dut, const duts::DutInfo& info)>;

// `hilrig run --host-link` values.
inline constexpr std::string_view kInProcessLink = "in-process";
inline constexpr std::string_view kModbusRtuPtyLink = "modbus-rtu-pty";

} // namespace hilrig::campaign
