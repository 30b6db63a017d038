// The candump log reader on any bytes, a line at a time. Invariant: whatever it reads, the
// writer writes back as a line that reads to the same record (reader and writer agree).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/candump.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    const auto record = hilrig::read_candump_line(line);
    if (!record) continue;
    const auto again = hilrig::read_candump_line(
        hilrig::candump_line(record->time, record->bus, record->frame, 0, record->fdf_flag));
    if (!again || !(*again == *record)) std::abort();
  }
  return 0;
}
