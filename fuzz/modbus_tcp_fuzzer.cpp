// Modbus TCP framing and the PDU handler on any byte stream, as a client sends it: the stream
// is cut into frames by the MBAP header alone and every request is answered. Invariants: a
// frame never claims more bytes than are there or none at all, and every answer is a whole
// ADU of at most 260 bytes with the request's transaction id.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "drivers/modbus/tcp_framing.hpp"
#include "fuzz/fuzz_register_map.hpp"

namespace m = hilrig::drivers::modbus;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hilrig::fuzz::FuzzRegisterMap map;
  std::span<const std::uint8_t> stream(data, size);
  std::vector<std::uint8_t> response;
  while (!stream.empty()) {
    const m::TcpFrame f = m::next_tcp_frame(stream);
    if (f.kind == m::TcpFrameKind::Incomplete || f.kind == m::TcpFrameKind::Invalid) break;
    if (f.length == 0 || f.length > stream.size() || f.length > m::kMaxTcpAdu) std::abort();
    if (f.kind == m::TcpFrameKind::Request) {
      response.clear();
      (void)m::answer_tcp_request(map, stream.first(f.length), response);
      if (response.size() < m::kMbapHeaderLength + 2 || response.size() > m::kMaxTcpAdu) std::abort();
      if (response[0] != stream[0] || response[1] != stream[1]) std::abort();
    }
    stream = stream.subspan(f.length);
  }
  return 0;
}
