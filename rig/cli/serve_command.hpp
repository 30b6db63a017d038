#pragma once
// `hilrig serve smd23e --modbus-tcp [ADDR:]PORT [--bind ADDR] [--fault NAME]`: runs a virtual
// device in real time as a Modbus TCP server (the SMD23E's map: input registers 0–9,
// holding registers 1024–1033). Its scheduler is advanced to the monotonic clock before
// each request and every poll period. Loopback only unless --bind says otherwise; stops
// cleanly on SIGINT/SIGTERM.

#include <CLI/CLI.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

namespace hilrig::cli {

struct ServeOptions {
  std::string device = "smd23e";
  std::string bind = "127.0.0.1";
  std::uint16_t port = 502; // 0: a free port, reported through on_listening
  std::string fault = "none";
  bool m12 = false;
  bool no_encoder = false;
};

// Serves until `stop` becomes true. on_listening gets the bound port once listening.
// Throws std::runtime_error for an unknown device/fault or a port it cannot bind.
void run_serve(const ServeOptions& options, const std::atomic<bool>& stop,
               const std::function<void(std::uint16_t port)>& on_listening = {});

void add_serve_command(CLI::App& app);

} // namespace hilrig::cli
