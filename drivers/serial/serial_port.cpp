#include "drivers/serial/serial_port.hpp"

#include <linux/serial.h>
#include <sys/ioctl.h>

#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "core/clock.hpp"

namespace hilrig::serial {

namespace asio = boost::asio;

namespace {

asio::serial_port::parity::type asio_parity(Parity p) {
  switch (p) {
  case Parity::Even:
    return asio::serial_port::parity::even;
  case Parity::Odd:
    return asio::serial_port::parity::odd;
  case Parity::None:
    break;
  }
  return asio::serial_port::parity::none;
}

} // namespace

SerialPort::SerialPort(asio::io_context& io, const SerialPortSettings& settings)
    : port_(io), device_(settings.device) {
  boost::system::error_code ec;
  port_.open(settings.device, ec);
  if (ec) throw std::system_error(ec, "serial port " + settings.device);
  const SerialFormat& f = settings.format;
  port_.set_option(asio::serial_port::baud_rate(f.baud), ec);
  if (!ec) port_.set_option(asio::serial_port::character_size(f.data_bits), ec);
  if (!ec) port_.set_option(asio::serial_port::parity(asio_parity(f.parity)), ec);
  if (!ec) {
    port_.set_option(asio::serial_port::stop_bits(f.stop_bits == 2 ? asio::serial_port::stop_bits::two
                                                                   : asio::serial_port::stop_bits::one),
                     ec);
  }
  if (!ec) port_.set_option(asio::serial_port::flow_control(asio::serial_port::flow_control::none), ec);
  if (ec) throw std::system_error(ec, "serial port " + settings.device + ": settings");
  if (settings.rs485) {
    // Only drivers with RS-485 support accept this; others (ptys, most USB adapters) refuse
    // and the caller sees rs485_active() == false.
    serial_rs485 rs{};
    rs.flags = SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND;
    rs485_active_ = ioctl(port_.native_handle(), TIOCSRS485, &rs) == 0;
  }
  start_read();
}

SerialPort::~SerialPort() { close(); }

void SerialPort::close() {
  boost::system::error_code ignored;
  port_.close(ignored);
}

void SerialPort::on_byte(ByteHandler handler) { handlers_.push_back(std::move(handler)); }

void SerialPort::write(std::span<const std::uint8_t> bytes) {
  const bool idle = write_queue_.empty();
  write_queue_.emplace_back(bytes.begin(), bytes.end());
  if (idle) start_write();
}

void SerialPort::start_write() {
  asio::async_write(port_, asio::buffer(write_queue_.front()),
                    [this](const boost::system::error_code& ec, std::size_t /*n*/) {
                      if (ec) {
                        if (!error_) error_ = ec;
                        write_queue_.clear();
                        return;
                      }
                      write_queue_.pop_front();
                      if (!write_queue_.empty()) start_write();
                    });
}

void SerialPort::start_read() {
  port_.async_read_some(asio::buffer(read_buffer_),
                        [this](const boost::system::error_code& ec, std::size_t n) {
                          if (ec) {
                            if (ec != asio::error::operation_aborted && !error_) error_ = ec;
                            return;
                          }
                          const Nanos stamp = MonotonicClock{}.now();
                          for (std::size_t i = 0; i < n; ++i) {
                            for (const auto& h : handlers_) h(read_buffer_[i], stamp);
                          }
                          start_read();
                        });
}

} // namespace hilrig::serial
