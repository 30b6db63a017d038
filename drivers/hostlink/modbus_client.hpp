#pragma once
// The rig's host link to a board's registers: a Modbus RTU (serial) or Modbus TCP client on
// libmodbus, behind the same core RegisterMap interface a virtual model implements — so a
// campaign's host actions run unchanged against the in-process model or a real link.
// Exception replies come back as RegisterStatus; failures on the wire throw HostLinkError.

#include <memory>
#include <string>

#include "core/register_map.hpp"
#include "core/serial.hpp"
#include "core/time.hpp"
#include "drivers/hostlink/host_link_error.hpp"

struct _modbus; // libmodbus's context

namespace hilrig::hostlink {

struct RtuSettings {
  std::string device; // e.g. /dev/ttyUSB0
  SerialFormat format{19200, 8, Parity::Even, 1};
  int unit = 1; // Modbus slave address
  Nanos response_timeout{500'000'000};
};

struct TcpSettings {
  std::string host = "127.0.0.1";
  int port = 502;
  int unit = 1;
  Nanos response_timeout{500'000'000};
};

class ModbusClient final : public RegisterMap {
public:
  // Connects; throws HostLinkError (ConnectionLost) naming the endpoint when it cannot.
  static std::unique_ptr<ModbusClient> rtu(const RtuSettings& settings);
  static std::unique_ptr<ModbusClient> tcp(const TcpSettings& settings);
  ~ModbusClient() override;
  ModbusClient(const ModbusClient&) = delete;
  ModbusClient& operator=(const ModbusClient&) = delete;

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

  [[nodiscard]] const std::string& endpoint() const { return endpoint_; }

private:
  ModbusClient(_modbus* ctx, std::string endpoint, Nanos timeout);
  // Turns libmodbus's errno after a failed call into a status or a thrown HostLinkError.
  RegisterStatus fail(const std::string& transaction);

  _modbus* ctx_;
  std::string endpoint_;
};

} // namespace hilrig::hostlink
