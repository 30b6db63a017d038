#pragma once
// A real serial port (on-board UART, USB adapter, pty) behind the core ByteLink interface,
// on Boost.Asio. It belongs to the non-RT side: reads complete on the io_context's thread
// and are stamped with CLOCK_MONOTONIC when they arrive.

#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>

#include <array>
#include <deque>
#include <string>
#include <system_error>
#include <vector>

#include "core/serial.hpp"

namespace hilrig::serial {

struct SerialPortSettings {
  std::string device;  // e.g. "/dev/ttyUSB0" or a pty's slave name
  SerialFormat format; // baud, data bits, parity, stop bits
  bool rs485 = false;  // ask the driver to switch an RS-485 transceiver's direction (TIOCSRS485)
};

class SerialPort final : public ByteLink {
public:
  // Opens and configures the port; throws std::system_error naming the device on failure.
  SerialPort(boost::asio::io_context& io, const SerialPortSettings& settings);
  ~SerialPort() override;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Queues bytes for writing; writes complete in order on the io_context.
  void write(std::span<const std::uint8_t> bytes) override;
  void on_byte(ByteHandler handler) override;

  // True when RS-485 direction control was asked for and the driver accepted it.
  [[nodiscard]] bool rs485_active() const { return rs485_active_; }
  // Writes queued and not yet completed.
  [[nodiscard]] std::size_t queued_writes() const { return write_queue_.size(); }
  // The first I/O error seen (empty when none): the port stops reading after it.
  [[nodiscard]] const std::error_code& error() const { return error_; }
  void close();

private:
  void start_read();
  void start_write();

  boost::asio::serial_port port_;
  std::string device_;
  std::array<std::uint8_t, 256> read_buffer_{};
  std::deque<std::vector<std::uint8_t>> write_queue_;
  std::vector<ByteHandler> handlers_;
  std::error_code error_;
  bool rs485_active_ = false;
};

} // namespace hilrig::serial
