#pragma once
// A Modbus TCP server on Boost.Asio that serves any RegisterMap to many clients at once.
// One io_context on the thread that calls run() owns the map and every connection, so the
// model stays single-threaded; nothing blocks it: reads and writes are asynchronous and each
// connection has its own buffers (framing: tcp_framing.hpp). Binds to loopback unless told
// otherwise (DESIGN.md, "safe by default"). The limits (docs/serve.md):
//   - at most max_connections at once; a client arriving at the limit takes the place of the
//     connection idle the longest (none with a reply in flight: then the newcomer is closed);
//   - a connection that neither sends nor takes a byte for idle_timeout is closed;
//   - a connection whose unsent replies would pass max_output_bytes (a client that sends and
//     never reads) is closed, so it holds neither memory nor anyone else up.
// A frame whose MBAP protocol id is not 0 is discarded; a length field no Modbus frame can
// have closes the connection (the stream cannot be resynced), once the requests that came
// before it are answered.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/register_map.hpp"
#include "core/time.hpp"
#include "drivers/modbus/pdu_handler.hpp"

namespace hilrig::drivers::modbus {

struct TcpLimits {
  std::size_t max_connections = 64;     // the real SMD23E takes 3 (its manual, L635)
  Nanos idle_timeout = seconds(60);     // no byte either way for this long: closed
  std::size_t max_output_bytes = 65536; // unsent reply bytes held for one connection
};

struct TcpServerOptions {
  std::string bind = "127.0.0.1"; // dotted IPv4 address
  std::uint16_t port = 502;       // 0: the OS picks a free port (see TcpServer::port())
  TcpLimits limits;
  Nanos poll_period = milliseconds(5);       // how often the tick runs while no request arrives
  Fc23Read fc23_read = Fc23Read::AfterWrite; // the served device's FC 23 (pdu_handler.hpp)
  // Told each time the server closes a connection itself, with the client's address and the
  // reason (an impossible length, idle, unread replies, replaced at the limit), so a lab sees
  // why a client lost its link; a client that leaves is not a server's close.
  std::function<void(const std::string& peer, const std::string& reason)> on_close;
};

// Counters, safe to read from another thread while the server runs. `open` and
// `buffered_bytes` are the server's bookkeeping now (a leak shows as a count that does not
// return to zero); `open` is notified on every change (std::atomic::wait).
struct TcpServerStats {
  std::atomic<std::uint64_t> requests{0};     // Modbus frames answered
  std::atomic<std::uint64_t> exceptions{0};   // of them, answered with an exception
  std::atomic<std::uint64_t> discarded{0};    // frames with a protocol id other than 0
  std::atomic<std::uint64_t> connections{0};  // connections accepted
  std::atomic<std::uint64_t> replaced{0};     // idle connections closed for a newcomer at the limit
  std::atomic<std::uint64_t> refused{0};      // newcomers closed at the limit (none idle)
  std::atomic<std::uint64_t> timed_out{0};    // connections closed after idle_timeout
  std::atomic<std::uint64_t> overflowed{0};   // connections closed at max_output_bytes
  std::atomic<std::uint64_t> bad_frames{0};   // connections closed for an impossible length
  std::atomic<std::size_t> open{0};           // connections open now
  std::atomic<std::size_t> buffered_bytes{0}; // reply bytes held for all connections now
};

class TcpServer {
public:
  // Binds and listens at once; throws std::runtime_error when it cannot.
  TcpServer(RegisterMap& map, TcpServerOptions options);
  TcpServer(const TcpServer&) = delete;
  TcpServer& operator=(const TcpServer&) = delete;
  ~TcpServer();

  [[nodiscard]] std::uint16_t port() const;
  [[nodiscard]] const TcpServerStats& stats() const;

  // Called before each request is answered and once per poll period: the place to advance
  // a model's scheduler to the present.
  void on_tick(std::function<void()> tick);

  // Serves until `stop` becomes true (checked once per poll period), then closes every
  // connection.
  void run(const std::atomic<bool>& stop);

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace hilrig::drivers::modbus
