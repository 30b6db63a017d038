#pragma once
// The host link over Modbus: the rig side turns each host word access into one register
// transaction on a RegisterMap client (a hostlink::ModbusClient), in the order the host
// sequence makes them: command word k is a write (FC16) of holding register command_base + k,
// status word k a read (FC4) of input register status_base + k. For a virtual DUT the board
// side is a PtyBoard: an RtuServer on a pty pair serving the DUT's words (DutRegisters).
//
// Lockstep: the simulation thread holds the turn mutex except while a transaction is in
// flight, and the board side takes it to touch the DUT, so virtual time stands still across
// a transaction and the DUT sees the same accesses at the same virtual times as in process.

#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>

#include "core/register_map.hpp"
#include "core/time.hpp"
#include "drivers/modbus/pty.hpp"
#include "drivers/modbus/rtu_server.hpp"
#include "rig/campaign/dut_registers.hpp"
#include "rig/campaign/host_link.hpp"

namespace hilrig::campaign {

class ModbusHostLink final : public HostWords {
public:
  // client: the rig's Modbus client. board: what the client talks to, kept alive with the link
  // and destroyed after the client. turn: the lockstep mutex the board side takes before it
  // touches the DUT (null for a board that does not share the DUT); held from here on.
  ModbusHostLink(std::unique_ptr<RegisterMap> client, const HostRegisters& at,
                 std::shared_ptr<std::mutex> turn, std::shared_ptr<void> board);
  ~ModbusHostLink() override;
  ModbusHostLink(const ModbusHostLink&) = delete;
  ModbusHostLink& operator=(const ModbusHostLink&) = delete;

  // Throw hostlink::HostLinkError on a failure of the line, std::runtime_error when the board
  // answers with a Modbus exception.
  void write(std::size_t word, std::uint16_t value) override;
  [[nodiscard]] std::uint16_t read(std::size_t word) override;

private:
  // Hands the DUT to the board side for the length of one transaction.
  class InFlight;

  HostRegisters at_;
  std::shared_ptr<std::mutex> turn_;
  std::unique_lock<std::mutex> held_;
  std::shared_ptr<void> board_;
  std::unique_ptr<RegisterMap> client_;
};

// A virtual DUT's board side on a new pty pair: an RtuServer (unit 1, 19200 8E1) on the master
// serving DutRegisters, on a Boost.Asio io_context of its own thread that answers a frame as
// soon as it arrives. A client opens device().
class PtyBoard {
public:
  PtyBoard(duts::Dut& dut, const HostRegisters& at, std::mutex& turn);
  ~PtyBoard(); // stops the thread
  PtyBoard(const PtyBoard&) = delete;
  PtyBoard& operator=(const PtyBoard&) = delete;

  [[nodiscard]] const std::string& device() const { return pty_.slave_path(); }
  [[nodiscard]] const drivers::modbus::RtuServerStats& stats() const { return server_.stats(); }

private:
  void wait_for_frame();

  drivers::modbus::Pty pty_;
  DutRegisters registers_;
  drivers::modbus::RtuServer server_;
  boost::asio::io_context io_;
  boost::asio::posix::stream_descriptor master_;
  std::thread thread_;
};

// The link of `hilrig run --host-link modbus-rtu-pty`: a PtyBoard serving `dut` and a
// ModbusClient on its pty, in lockstep.
[[nodiscard]] std::unique_ptr<HostWords> modbus_rtu_pty_link(duts::Dut& dut, const HostRegisters& at,
                                                             Nanos response_timeout = milliseconds(500));

} // namespace hilrig::campaign
