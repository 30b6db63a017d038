// Figure 6a: CAN frames per second the rig sends and timestamps, through drivers/socketcan.
// One CanSocket sends N classic frames (id 0x123, 8 bytes, a sequence number in the first four)
// as fast as the interface takes them, a batch per sendmmsg (CanSocket::send_batch); a second
// CanSocket on the same interface receives them on another thread, a batch per recvmmsg with
// each frame's kernel receive timestamp, and checks every sequence number.
// The rate is read from those timestamps, (N - 1) / (last - first), as the peer's is read from
// candump's log, so both figures come from the same clock by the same rule.
//
// Usage: bench_can_frames IFACE FRAMES [RCVBUF_BYTES]   (prints key=value lines)
#include <sys/socket.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string>
#include <thread>

#include "core/clock.hpp"
#include "drivers/socketcan/can_socket.hpp"

using namespace hilrig;
using namespace hilrig::socketcan;

namespace {

struct Received {
  std::uint64_t frames = 0;
  std::uint64_t out_of_order = 0; // a sequence number other than the next expected one
  Nanos first{0};
  Nanos last{0};
};

// The receiver's queue must hold what the sender can get ahead by, or frames are dropped
// (vcan has no flow control): the same size candump gets with -r.
void set_receive_buffer(int fd, int bytes) {
  if (setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &bytes, sizeof(bytes)) != 0) {
    setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof(bytes));
  }
}

Received receive_all(CanSocket& rx, std::uint64_t frames) {
  Received r;
  std::uint32_t expected = 0;
  std::array<CanReceived, CanSocket::kBatch> batch{};
  while (r.frames < frames) {
    const std::size_t n = rx.receive_batch(batch, seconds(2)); // waits only when nothing is queued
    if (n == 0) break;                                         // nothing for 2 s: the rest were lost
    for (std::size_t k = 0; k < n; ++k) {
      const CanReceived& got = batch[k];
      if (got.is_error || got.frame.id != 0x123 || got.frame.len != 8) continue;
      std::uint32_t seq = 0;
      std::memcpy(&seq, got.frame.data.data(), sizeof(seq));
      if (seq != expected) ++r.out_of_order;
      expected = seq + 1;
      if (r.frames == 0) r.first = got.timestamp;
      r.last = got.timestamp;
      ++r.frames;
    }
  }
  return r;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s IFACE FRAMES [RCVBUF_BYTES]\n", argv[0]);
    return 2;
  }
  const std::string iface = argv[1];
  const auto frames = std::strtoull(argv[2], nullptr, 10);
  const int rcvbuf = argc > 3 ? std::atoi(argv[3]) : 32 << 20;
  if (frames < 2 || frames > 0xFFFFFFFFULL) {
    std::fprintf(stderr, "bench_can_frames: FRAMES must be 2..2^32-1\n");
    return 2;
  }
  try {
    // The receiver takes id 0x123 only, as candump's vcan0,123:7FF; the sender receives
    // nothing, as cangen's socket (an empty filter list).
    CanSocketOptions rx_options;
    rx_options.error_frames = false;
    rx_options.filters.push_back(CanFilter{0x123, 0x7FF, false});
    CanSocket rx(iface, rx_options);
    set_receive_buffer(rx.fd(), rcvbuf);
    CanSocketOptions tx_options;
    tx_options.error_frames = false;
    tx_options.data_frames = false;
    CanSocket tx(iface, tx_options);
    Received got;
    std::thread receiver([&] { got = receive_all(rx, frames); });

    std::array<CanFrame, CanSocket::kBatch> burst{};
    for (CanFrame& f : burst) {
      f.id = 0x123;
      f.len = 8;
    }
    std::uint64_t not_sent = 0;
    const MonotonicClock clock;
    const Nanos start = clock.now();
    // One deadline for the burst, as a rig sending a burst sets it (a clock read per frame
    // would be the bench's cost, not the socket's: under QEMU it is a syscall).
    const Nanos deadline = start + seconds(30);
    for (std::uint64_t i = 0; i < frames;) {
      const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(burst.size(), frames - i));
      for (std::size_t k = 0; k < n; ++k) {
        const auto seq = static_cast<std::uint32_t>(i + k);
        std::memcpy(burst[k].data.data(), &seq, sizeof(seq));
      }
      const BatchSent sent = tx.send_batch(std::span<const CanFrame>(burst.data(), n), deadline);
      not_sent += n - sent.sent;
      i += n;
    }
    const Nanos sent = clock.now();
    receiver.join();
    const Nanos done = clock.now();

    const double span_s = static_cast<double>((got.last - got.first).count()) * 1e-9;
    std::printf("interface=%s\nframes=%llu\nnot_sent=%llu\nreceived=%llu\nlost=%llu\nout_of_order=%llu\n",
                iface.c_str(), static_cast<unsigned long long>(frames),
                static_cast<unsigned long long>(not_sent), static_cast<unsigned long long>(got.frames),
                static_cast<unsigned long long>(frames - got.frames),
                static_cast<unsigned long long>(got.out_of_order));
    std::printf("kernel_span_s=%.6f\nfps=%.1f\nsend_wall_s=%.6f\nwall_s=%.6f\n", span_s,
                span_s > 0 ? static_cast<double>(got.frames - 1) / span_s : 0.0,
                static_cast<double>((sent - start).count()) * 1e-9,
                static_cast<double>((done - start).count()) * 1e-9);
    return got.frames == frames && got.out_of_order == 0 && not_sent == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_can_frames: %s\n", e.what());
    return 2;
  }
}
