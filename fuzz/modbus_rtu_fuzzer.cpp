// Modbus RTU framing and the PDU handler on any bytes received since the line was idle, as
// a serial client sends them: the first byte picks this server's unit id, the rest is the
// line. Frames are cut as the server cuts them, first while bytes still arrive, then after
// the 3.5-character silence. Invariants: a frame never claims more bytes than are there,
// and every answer is at most 256 bytes with a good CRC.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "drivers/modbus/rtu_framing.hpp"
#include "fuzz/fuzz_register_map.hpp"

namespace m = hilrig::drivers::modbus;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t unit = data[0];
  hilrig::fuzz::FuzzRegisterMap map;
  std::span<const std::uint8_t> line(data + 1, size - 1);
  std::vector<std::uint8_t> response;
  for (const bool silent : {false, true}) {
    while (!line.empty()) {
      const m::RtuFrame f = m::next_rtu_frame(line, silent);
      if (f.kind == m::RtuFrameKind::Incomplete) break;
      if (f.length == 0 || f.length > line.size()) std::abort();
      if (f.kind == m::RtuFrameKind::Request) {
        response.clear();
        const m::RtuAnswer a = m::answer_rtu_request(map, unit, line.first(f.length), response);
        if (!response.empty() && (response.size() > m::kMaxRtuAdu || !m::rtu_crc_ok(response))) std::abort();
        if (!a.addressed && !response.empty()) std::abort();
      }
      line = line.subspan(f.length);
    }
  }
  return 0;
}
