#pragma once
// A Modbus TCP server on libmodbus that serves any RegisterMap. Framing comes from
// libmodbus (modbus_receive), exceptions are sent with modbus_reply_exception, and the
// protocol logic is handle_pdu(). Binds to loopback unless told otherwise (DESIGN.md,
// "safe by default"). Single-threaded: the map is only touched from run()/serve_once().

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/register_map.hpp"
#include "core/time.hpp"

typedef struct _modbus modbus_t; // NOLINT: libmodbus's own opaque type

namespace hilrig::drivers::modbus {

struct TcpServerOptions {
  std::string bind = "127.0.0.1";      // dotted IPv4 address
  std::uint16_t port = 502;            // 0: the OS picks a free port (see TcpServer::port())
  int max_connections = 3;             // the SMD23E accepts up to 3 (spec §2.4)
  Nanos poll_period = milliseconds(5); // how often the tick runs while no request arrives
};

struct TcpServerStats {
  std::uint64_t requests = 0;
  std::uint64_t exceptions = 0;
  std::uint64_t connections = 0;
};

class TcpServer {
public:
  // Binds and listens at once; throws std::runtime_error when it cannot.
  TcpServer(RegisterMap& map, TcpServerOptions options);
  TcpServer(const TcpServer&) = delete;
  TcpServer& operator=(const TcpServer&) = delete;
  ~TcpServer();

  [[nodiscard]] std::uint16_t port() const { return port_; }
  [[nodiscard]] const TcpServerStats& stats() const { return stats_; }

  // Called before each request is answered and once per poll period: the place to advance
  // a model's scheduler to the present.
  void on_tick(std::function<void()> tick) { tick_ = std::move(tick); }

  // Serves until `stop` becomes true (checked at least once per poll period).
  void run(const std::atomic<bool>& stop);
  // One round: waits up to the poll period, accepts and answers what arrived.
  void serve_once();

private:
  void accept_client();
  bool answer(int fd); // false when the connection is gone
  void close_client(std::size_t index);

  RegisterMap& map_;
  TcpServerOptions options_;
  modbus_t* ctx_ = nullptr;
  int listen_fd_ = -1;
  std::uint16_t port_ = 0;
  std::vector<int> clients_;
  std::function<void()> tick_;
  TcpServerStats stats_;
};

} // namespace hilrig::drivers::modbus
