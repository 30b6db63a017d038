#pragma once
// A Modbus RTU server that serves any RegisterMap over a serial device or a pty. libmodbus
// opens and configures the serial line (termios, RS-485 mode); frames are cut and answered
// by rtu_framing.hpp (by length when the function code fixes it, else at the 3.5-character
// silence), so an unknown function gets exception 01 and the next request is read cleanly.
// It answers only its own unit id; a broadcast (unit 0) write is carried out and never
// answered (Modbus over Serial Line v1.02, §2.2); a frame with a bad CRC is counted and
// dropped, and the server keeps listening.
// Single-threaded: the map is only touched from run()/serve_once(); stats() may be read from
// any thread.

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/register_map.hpp"
#include "core/serial.hpp"
#include "core/time.hpp"
#include "drivers/modbus/rtu_framing.hpp"

typedef struct _modbus modbus_t; // NOLINT: libmodbus's own opaque type

namespace hilrig::drivers::modbus {

struct RtuServerOptions {
  std::string device;                             // serial device path, e.g. /dev/ttyUSB0
  SerialFormat format{19200, 8, Parity::Even, 1}; // Modbus RTU's default framing
  std::uint8_t unit = 1;                          // 1..247
  bool rs485 = false;                             // ask the port for RS-485 mode
  Nanos poll_period = milliseconds(5);            // how often the tick runs while idle
  Fc23Read fc23_read = Fc23Read::AfterWrite;      // the served device's FC 23 (pdu_handler.hpp)
  // How long a frame whose function fixes its length waits for its next byte. Below the
  // 3.5-character silence (0, the default) it is the silence: a gap ends the frame (Serial Line
  // v1.02 §2.5.1.1), so another slave's reply on a shared bus is not joined to the next request.
  // A USB adapter or an emulated UART that delivers a frame in bursts needs more (e.g. 100 ms),
  // at the price of joining a frame cut short to whatever comes next within that time.
  Nanos byte_timeout{0};
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
  // One round: waits up to the poll period for a frame to begin, then reads until it is
  // whole (by its length, or a silence of 3.5 characters) and answers it.
  void serve_once();

private:
  bool wait_readable(Nanos timeout) const;
  bool read_more();
  void take(const RtuFrame& frame);
  void send(std::span<const std::uint8_t> bytes);

  RegisterMap& map_;
  RtuServerOptions options_;
  modbus_t* ctx_ = nullptr;
  bool owns_device_ = false;
  bool rs485_active_ = false;
  std::string rs485_note_;
  int fd_ = -1;
  Nanos silence_;
  std::array<std::uint8_t, 2 * kMaxRtuAdu> in_{}; // bytes since the line was last idle
  std::size_t pending_ = 0;
  std::vector<std::uint8_t> out_;
  std::function<void()> tick_;
  RtuServerStats stats_;
};

} // namespace hilrig::drivers::modbus
