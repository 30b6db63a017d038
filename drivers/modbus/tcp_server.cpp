#include "drivers/modbus/tcp_server.hpp"

#include <fmt/format.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <list>
#include <span>
#include <stdexcept>
#include <vector>

#include "drivers/modbus/tcp_framing.hpp"

namespace hilrig::drivers::modbus {

namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;
using boost::system::error_code;

std::chrono::nanoseconds chrono(Nanos t) { return std::chrono::nanoseconds(t.count()); }

struct Connection {
  explicit Connection(tcp::socket s) : socket(std::move(s)) {}
  tcp::socket socket;
  std::array<std::uint8_t, kMaxTcpAdu> in{}; // one whole frame fits: the rest waits in the kernel
  std::size_t in_length = 0;
  std::vector<std::uint8_t> pending;   // replies not yet handed to the socket
  std::vector<std::uint8_t> in_flight; // replies the socket is writing
  bool writing = false;
  bool open = true;
  bool closing = false; // no more reading: closed once the replies owed are written
  Clock::time_point last_activity;
  std::list<std::shared_ptr<Connection>>::iterator self;
  std::string peer;         // "address:port", for the reason a server's close gives
  std::string close_reason; // set when the server decided to close (closing, or at once)

  [[nodiscard]] std::size_t held() const { return pending.size() + in_flight.size(); }
};
using ConnectionPtr = std::shared_ptr<Connection>;

} // namespace

class TcpServer::Impl {
public:
  Impl(RegisterMap& map, TcpServerOptions options);

  void run(const std::atomic<bool>& stop);

  RegisterMap& map_;
  TcpServerOptions options_;
  asio::io_context io_;
  tcp::acceptor acceptor_;
  asio::steady_timer ticker_;
  std::uint16_t port_ = 0;
  std::function<void()> tick_;
  TcpServerStats stats_;

private:
  void accept();
  void admit(tcp::socket socket);
  void read(const ConnectionPtr& c);
  bool take_frames(const ConnectionPtr& c);
  void write(const ConnectionPtr& c);
  void close(const ConnectionPtr& c);
  // The server closes: `reason` goes to options_.on_close.
  void close_for(const ConnectionPtr& c, std::string reason);
  void arm_ticker();
  void close_idle();
  void count_open();

  std::list<ConnectionPtr> connections_;
  const std::atomic<bool>* stop_ = nullptr;
  bool accepting_ = false;
};

TcpServer::Impl::Impl(RegisterMap& map, TcpServerOptions options)
    : map_(map), options_(std::move(options)), acceptor_(io_), ticker_(io_) {
  error_code ec;
  const asio::ip::address_v4 address = asio::ip::make_address_v4(options_.bind, ec);
  if (ec) {
    throw std::runtime_error("modbus tcp: not an IPv4 address: " + options_.bind);
  }
  const tcp::endpoint at(address, options_.port);
  if (acceptor_.open(at.protocol(), ec) || acceptor_.set_option(tcp::acceptor::reuse_address(true), ec) ||
      acceptor_.bind(at, ec) || acceptor_.listen(asio::socket_base::max_listen_connections, ec)) {
    throw std::runtime_error("modbus tcp: cannot listen on " + options_.bind + ":" +
                             std::to_string(options_.port) + ": " + ec.message());
  }
  port_ = acceptor_.local_endpoint().port();
}

void TcpServer::Impl::run(const std::atomic<bool>& stop) {
  stop_ = &stop;
  accept();
  arm_ticker();
  io_.run();
  io_.restart();
}

void TcpServer::Impl::accept() {
  accepting_ = true;
  acceptor_.async_accept([this](const error_code& ec, tcp::socket socket) {
    accepting_ = false;
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) {
      return;
    }
    if (!ec) {
      admit(std::move(socket));
      accept();
    } // else (out of descriptors, say): the ticker tries again next period
  });
}

void TcpServer::Impl::admit(tcp::socket socket) {
  if (connections_.size() >= options_.limits.max_connections) {
    const auto longest_idle = std::min_element(
        connections_.begin(), connections_.end(),
        [](const ConnectionPtr& a, const ConnectionPtr& b) { return a->last_activity < b->last_activity; });
    if (longest_idle != connections_.end()) {
      ++stats_.replaced;
      close_for(ConnectionPtr(*longest_idle),
                fmt::format("replaced by a newcomer: {} connections at once at most (--max-connections)",
                            options_.limits.max_connections));
    }
  }
  error_code ignored;
  socket.set_option(tcp::no_delay(true), ignored); // a reply is one small segment: send it now
  auto c = std::make_shared<Connection>(std::move(socket));
  const tcp::endpoint peer = c->socket.remote_endpoint(ignored);
  c->peer = fmt::format("{}:{}", peer.address().to_string(), peer.port());
  c->last_activity = Clock::now();
  c->self = connections_.insert(connections_.end(), c);
  ++stats_.connections;
  count_open();
  read(c);
}

void TcpServer::Impl::read(const ConnectionPtr& c) {
  const asio::mutable_buffer room(c->in.data() + c->in_length, c->in.size() - c->in_length);
  c->socket.async_read_some(room, [this, c](const error_code& ec, std::size_t n) {
    if (!c->open) {
      return;
    }
    if (ec) {
      close(c); // the client left (EOF) or the socket failed
      return;
    }
    c->in_length += n;
    c->last_activity = Clock::now();
    const bool keep_reading = take_frames(c);
    if (!c->open) {
      return;
    }
    write(c);
    if (keep_reading) {
      read(c);
    }
  });
}

// Answers every whole frame in the input buffer; false when nothing more is to be read from
// the connection (it was closed, or is closing once its replies are written).
bool TcpServer::Impl::take_frames(const ConnectionPtr& c) {
  std::size_t at = 0;
  for (;;) {
    const std::span<const std::uint8_t> rest(c->in.data() + at, c->in_length - at);
    const TcpFrame frame = next_tcp_frame(rest);
    if (frame.kind == TcpFrameKind::Incomplete) {
      break;
    }
    if (frame.kind == TcpFrameKind::Invalid) {
      // Nothing after it can be framed, but the requests before it were taken: their replies
      // are owed, so the connection closes once they are written (write()).
      ++stats_.bad_frames;
      c->closing = true;
      c->close_reason = fmt::format("MBAP length {} outside 2 .. {} (unit id + a PDU of at most {} bytes)",
                                    (std::size_t{rest[4]} << 8U) | rest[5], 1 + kMaxTcpPdu, kMaxTcpPdu);
      return false;
    }
    if (frame.kind == TcpFrameKind::Foreign) {
      ++stats_.discarded;
    } else {
      if (tick_) {
        tick_();
      }
      const std::size_t before = c->pending.size();
      const RegisterStatus status =
          answer_tcp_request(map_, rest.first(frame.length), c->pending, options_.fc23_read);
      stats_.buffered_bytes += c->pending.size() - before;
      ++stats_.requests;
      if (status != RegisterStatus::Ok) {
        ++stats_.exceptions;
      }
      if (c->held() > options_.limits.max_output_bytes) {
        ++stats_.overflowed; // it sends and does not read: it may not hold the server's memory
        close_for(c, fmt::format("more than {} reply bytes unread (--max-output)",
                                 options_.limits.max_output_bytes));
        return false;
      }
    }
    at += frame.length;
  }
  std::copy(c->in.begin() + static_cast<std::ptrdiff_t>(at),
            c->in.begin() + static_cast<std::ptrdiff_t>(c->in_length), c->in.begin());
  c->in_length -= at;
  return true;
}

void TcpServer::Impl::write(const ConnectionPtr& c) {
  if (c->writing) {
    return;
  }
  if (c->pending.empty()) {
    if (c->closing) {
      close_for(c, c->close_reason);
    }
    return;
  }
  std::swap(c->pending, c->in_flight);
  c->writing = true;
  asio::async_write(c->socket, asio::buffer(c->in_flight), [this, c](const error_code& ec, std::size_t) {
    if (!c->open) {
      return;
    }
    if (ec) {
      close(c);
      return;
    }
    stats_.buffered_bytes -= c->in_flight.size();
    c->in_flight.clear();
    c->writing = false;
    c->last_activity = Clock::now();
    write(c);
  });
}

void TcpServer::Impl::close_for(const ConnectionPtr& c, std::string reason) {
  if (!c->open) {
    return;
  }
  if (options_.on_close) {
    options_.on_close(c->peer, reason);
  }
  close(c);
}

// Closes at once; the handlers still queued for it see `open` false and return.
void TcpServer::Impl::close(const ConnectionPtr& c) {
  if (!c->open) {
    return;
  }
  c->open = false;
  error_code ignored;
  c->socket.close(ignored);
  stats_.buffered_bytes -= c->held();
  c->pending.clear(); // in_flight stays: a cancelled write may still point into it
  connections_.erase(c->self);
  count_open();
}

void TcpServer::Impl::count_open() {
  stats_.open.store(connections_.size());
  stats_.open.notify_all();
}

void TcpServer::Impl::arm_ticker() {
  ticker_.expires_after(chrono(options_.poll_period));
  ticker_.async_wait([this](const error_code& ec) {
    if (ec) {
      return;
    }
    if (tick_) {
      tick_();
    }
    if (stop_->load()) {
      error_code ignored;
      acceptor_.close(ignored);
      while (!connections_.empty()) {
        close(ConnectionPtr(connections_.front()));
      }
      return; // nothing left to wait for: io_.run() returns once the cancelled handlers ran
    }
    close_idle();
    if (!accepting_) {
      accept();
    }
    arm_ticker();
  });
}

void TcpServer::Impl::close_idle() {
  const Clock::time_point now = Clock::now();
  const auto timeout = chrono(options_.limits.idle_timeout);
  for (auto it = connections_.begin(); it != connections_.end();) {
    const ConnectionPtr c = *it++;
    if (now - c->last_activity >= timeout) {
      ++stats_.timed_out;
      close_for(c, fmt::format("no byte either way for {} ms (--idle-timeout)",
                               options_.limits.idle_timeout.count() / 1'000'000));
    }
  }
}

TcpServer::TcpServer(RegisterMap& map, TcpServerOptions options)
    : impl_(std::make_unique<Impl>(map, std::move(options))) {}
TcpServer::~TcpServer() = default;
std::uint16_t TcpServer::port() const { return impl_->port_; }
const TcpServerStats& TcpServer::stats() const { return impl_->stats_; }
void TcpServer::on_tick(std::function<void()> tick) { impl_->tick_ = std::move(tick); }
void TcpServer::run(const std::atomic<bool>& stop) { impl_->run(stop); }

} // namespace hilrig::drivers::modbus
