#include "drivers/hostlink/modbus_client.hpp"

#include <fmt/core.h>
#include <modbus/modbus.h>

#include <cerrno>

namespace hilrig::hostlink {

namespace {

char parity_letter(Parity p) { return p == Parity::Even ? 'E' : p == Parity::Odd ? 'O' : 'N'; }

void set_timeout(modbus_t* ctx, Nanos t) {
  const auto us = t.count() / 1'000;
  modbus_set_response_timeout(ctx, static_cast<std::uint32_t>(us / 1'000'000),
                              static_cast<std::uint32_t>(us % 1'000'000));
}

} // namespace

ModbusClient::ModbusClient(modbus_t* ctx, std::string endpoint, Nanos timeout)
    : ctx_(ctx), endpoint_(std::move(endpoint)) {
  set_timeout(ctx_, timeout);
}

ModbusClient::~ModbusClient() {
  modbus_close(ctx_);
  modbus_free(ctx_);
}

std::unique_ptr<ModbusClient> ModbusClient::rtu(const RtuSettings& s) {
  const std::string endpoint = fmt::format("modbus-rtu {} unit {}", s.device, s.unit);
  modbus_t* ctx = modbus_new_rtu(s.device.c_str(), static_cast<int>(s.format.baud),
                                 parity_letter(s.format.parity), s.format.data_bits, s.format.stop_bits);
  if (ctx == nullptr) throw HostLinkError(LinkFailure::Other, endpoint, modbus_strerror(errno));
  std::unique_ptr<ModbusClient> client(new ModbusClient(ctx, endpoint, s.response_timeout));
  if (modbus_set_slave(ctx, s.unit) != 0 || modbus_connect(ctx) != 0) {
    throw HostLinkError(LinkFailure::ConnectionLost, endpoint, modbus_strerror(errno));
  }
  return client;
}

std::unique_ptr<ModbusClient> ModbusClient::tcp(const TcpSettings& s) {
  const std::string endpoint = fmt::format("modbus-tcp {}:{} unit {}", s.host, s.port, s.unit);
  modbus_t* ctx = modbus_new_tcp(s.host.c_str(), s.port);
  if (ctx == nullptr) throw HostLinkError(LinkFailure::Other, endpoint, modbus_strerror(errno));
  std::unique_ptr<ModbusClient> client(new ModbusClient(ctx, endpoint, s.response_timeout));
  if (modbus_set_slave(ctx, s.unit) != 0 || modbus_connect(ctx) != 0) {
    throw HostLinkError(LinkFailure::ConnectionLost, endpoint, modbus_strerror(errno));
  }
  return client;
}

RegisterStatus ModbusClient::fail(const std::string& transaction) {
  const int err = errno;
  const std::string what = endpoint_ + ": " + transaction;
  // Exception replies are the device's answer, not a link failure.
  if (err > MODBUS_ENOBASE && err <= MODBUS_ENOBASE + MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE) {
    return static_cast<RegisterStatus>(err - MODBUS_ENOBASE);
  }
  switch (err) {
  case ETIMEDOUT:
    throw HostLinkError(LinkFailure::Timeout, what, modbus_strerror(err));
  case EMBBADCRC:
    throw HostLinkError(LinkFailure::BadCrc, what, modbus_strerror(err));
  case EMBBADDATA:
  case EMBBADEXC:
  case EMBMDATA:
  case EMBBADSLAVE:
    throw HostLinkError(LinkFailure::BadReply, what, modbus_strerror(err));
  case ECONNRESET:
  case ECONNREFUSED:
  case EPIPE:
  case EBADF:
    throw HostLinkError(LinkFailure::ConnectionLost, what, modbus_strerror(err));
  default:
    throw HostLinkError(LinkFailure::Other, what, modbus_strerror(err));
  }
}

RegisterStatus ModbusClient::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const int n = static_cast<int>(out.size());
  if (modbus_read_input_registers(ctx_, address, n, out.data()) == n) return RegisterStatus::Ok;
  return fail(fmt::format("read input registers {}..{}", address, address + out.size() - 1));
}

RegisterStatus ModbusClient::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const int n = static_cast<int>(out.size());
  if (modbus_read_registers(ctx_, address, n, out.data()) == n) return RegisterStatus::Ok;
  return fail(fmt::format("read holding registers {}..{}", address, address + out.size() - 1));
}

RegisterStatus ModbusClient::write_holding_registers(std::uint16_t address,
                                                     std::span<const std::uint16_t> values) {
  const int n = static_cast<int>(values.size());
  if (modbus_write_registers(ctx_, address, n, values.data()) == n) return RegisterStatus::Ok;
  return fail(fmt::format("write holding registers {}..{}", address, address + values.size() - 1));
}

} // namespace hilrig::hostlink
