#pragma once
// A Modbus RTU server on libmodbus that serves any RegisterMap over a serial device or a pty.
// Framing and CRC checking come from libmodbus (modbus_receive); the protocol logic is
// handle_pdu(), shared with TcpServer. It answers only its own unit id; a broadcast (unit 0)
// write is carried out and never answered (Modbus over Serial Line v1.02, §2.2); a frame with
// a bad CRC is counted and dropped, and the server keeps listening.
// Single-threaded: the map is only touched from run()/serve_once(); stats() may be read from
// any thread.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/register_map.hpp"
#include "core/serial.hpp"
#include "core/time.hpp"

typedef struct _modbus modbus_t; // NOLINT: libmodbus's own opaque type

namespace hilrig::drivers::modbus {

struct RtuServerOptions {
  std::string device;                             // serial device path, e.g. /dev/ttyUSB0
  SerialFormat format{19200, 8, Parity::Even, 1}; // Modbus RTU's default framing
  std::uint8_t unit = 1;                          // 1..247
  bool rs485 = false;                             // ask the port for RS-485 mode
  Nanos poll_period = milliseconds(5);            // how often the tick runs while idle
};

// Counters, safe to read from another thread while the server runs.
struct RtuServerStats {
  std::atomic<std::uint64_t> requests{0};   // frames for this unit (or broadcast) with a good CRC
  std::atomic<std::uint64_t> exceptions{0}; // exception replies sent
  std::atomic<std::uint64_t> crc_errors{0}; // frames dropped for a bad CRC
  std::atomic<std::uint64_t> other_unit{0}; // frames for another unit id, ignored
  std::atomic<std::uint64_t> broadcasts{0}; // broadcast frames (carried out, never answered)
};

class RtuServer {
public:
  // Opens and configures the serial device; throws std::runtime_error when it cannot. When
  // rs485 is asked of a port that cannot do it, the server serves in its default mode and
  // rs485_note() says why (the CLI reports it).
  RtuServer(RegisterMap& map, RtuServerOptions options);
  // Serves on an already open file descriptor (the master side of a pty: see Pty); the
  // server does not take ownership of fd and leaves its terminal settings alone.
  RtuServer(RegisterMap& map, int fd, RtuServerOptions options);
  RtuServer(const RtuServer&) = delete;
  RtuServer& operator=(const RtuServer&) = delete;
  ~RtuServer();

  [[nodiscard]] const RtuServerStats& stats() const { return stats_; }
  [[nodiscard]] bool rs485_active() const { return rs485_active_; }
  [[nodiscard]] const std::string& rs485_note() const { return rs485_note_; }

  // Called before each request is answered and once per poll period.
  void on_tick(std::function<void()> tick) { tick_ = std::move(tick); }

  // Serves until `stop` becomes true (checked at least once per poll period).
  void run(const std::atomic<bool>& stop);
  // One round: waits up to the poll period, answers a frame if one arrived.
  void serve_once();

private:
  void answer();
  void skip_foreign_reply();

  RegisterMap& map_;
  RtuServerOptions options_;
  modbus_t* ctx_ = nullptr;
  bool owns_device_ = false;
  bool rs485_active_ = false;
  std::string rs485_note_;
  std::function<void()> tick_;
  RtuServerStats stats_;
};

} // namespace hilrig::drivers::modbus
