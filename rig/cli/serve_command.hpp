#pragma once
// `hilrig serve DEVICE` runs a virtual device (serve_devices.hpp) in real time behind one
// Modbus link:
//   --modbus-tcp [ADDR:]PORT [--bind ADDR]     Modbus TCP, loopback unless --bind says otherwise,
//       [--max-connections N --idle-timeout T --max-output BYTES]   its limits (docs/serve.md)
//   --modbus-rtu PATH [--baud B --parity N|E|O --data-bits 7|8 --stop-bits 1|2 --unit U --rs485]
//   --pty [--unit U ...]                       Modbus RTU on a new pty pair; prints (and writes
//                                              to --port-file) the slave path a client opens
// and, with --far FAR.toml [--gpio-sim DIR] [--can IFACE], the model's pins on real kernel
// interfaces (serve_far_side.hpp), read and pulled every --tick (default 5 ms). --scan sets the
// ANS1's scan period, so a slow host (QEMU's emulated CPU) keeps the model in real time.
// The model's scheduler is advanced to the monotonic clock before each request is answered
// and every poll period. Stops cleanly on SIGINT/SIGTERM.

#include "rig/cli/cli_fwd.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/serial.hpp"
#include "drivers/modbus/rtu_server.hpp"
#include "drivers/modbus/tcp_server.hpp"
#include "rig/cli/serve_far_side.hpp"

namespace hilrig::cli {

enum class ServeLink : std::uint8_t { Tcp, Rtu, Pty };

struct ServeOptions {
  std::string device = "smd23e";
  ServeLink link = ServeLink::Tcp;
  // Modbus TCP
  std::string bind = "127.0.0.1";
  std::uint16_t port = 502;              // 0: a free port, reported through on_listening / on_ready
  drivers::modbus::TcpLimits tcp_limits; // connections, idle timeout, output bound (docs/serve.md)
  // Modbus RTU (Rtu: serial_device is opened; Pty: a new pty pair is made)
  std::string serial_device;
  SerialFormat format{19200, 8, Parity::Even, 1};
  std::uint8_t unit = 1;
  bool rs485 = false;
  Nanos byte_timeout{0}; // a fixed-length frame's wait for its next byte (RtuServerOptions)
  // The model
  std::string fault = "none";
  bool m12 = false;
  bool no_encoder = false;
  // The device's [MODEL] choices as "KEY=VALUE" (its campaign adapter's names, `hilrig list`)
  // and, for pls2700, the built-in transducer's motion ("constant:300rpm").
  std::vector<std::string> params;
  std::string motion;
  // The far side: the model's pins on gpio-sim and CAN (none when far.config is empty), and
  // how often the model runs and its pins are read while no request arrives.
  FarSideOptions far;
  Nanos tick = milliseconds(5);
  std::optional<Nanos> scan_period; // ans1: --scan
};

// What a client needs to reach the served device; valid while serve_device runs.
struct ServeEndpoint {
  ServeLink link = ServeLink::Tcp;
  std::uint16_t port = 0;  // Tcp: the bound port
  std::string serial_path; // Rtu: the device; Pty: the slave path a client opens
  std::string note;        // e.g. why RS-485 mode is off; empty when all is as asked
  const drivers::modbus::RtuServerStats* rtu_stats = nullptr; // Rtu/Pty
  const drivers::modbus::TcpServerStats* tcp_stats = nullptr; // Tcp
  std::string far_side;                                       // what the far side carries; empty without one
};

// Serves until `stop` becomes true; on_ready is called once the link is up.
// Throws std::invalid_argument for an unknown device or fault, std::runtime_error for a
// link it cannot open.
void serve_device(const ServeOptions& options, const std::atomic<bool>& stop,
                  const std::function<void(const ServeEndpoint&)>& on_ready);

void add_serve_command(CLI::App& app);

} // namespace hilrig::cli
