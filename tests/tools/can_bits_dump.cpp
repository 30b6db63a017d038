// Prints can_frame_bits() for seeded random frames of every format (classic/FD, standard/
// extended, remote, BRS) for can_frame_bits.py --check-exe to recompute independently.
// Line: "<ext> <fd> <brs> <rtr> <id hex> <data hex|-|R<dlc>> <nominal> <data> <stuff>".
#include <cstdio>
#include <random>

#include "drivers/virtual/can_bus.hpp"

using namespace hilrig;

int main() {
  std::mt19937 rng(11898);
  auto next = [&rng] { return static_cast<std::uint32_t>(rng()); };
  static constexpr std::uint8_t kFdLengths[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  for (int i = 0; i < 2000; ++i) {
    CanFrame f;
    f.extended = next() % 2 == 0;
    f.fd = next() % 2 == 0;
    f.id = next() & (f.extended ? 0x1FFF'FFFFU : 0x7FFU);
    if (f.fd) {
      f.brs = next() % 2 == 0;
      f.len = kFdLengths[next() % 16];
    } else {
      f.rtr = next() % 8 == 0;
      f.len = static_cast<std::uint8_t>(next() % 9);
    }
    // Runs of equal bits are what stuffing is about: mix random bytes with 0x00 and 0xFF.
    for (std::size_t k = 0; k < f.len; ++k) {
      const unsigned pick = next() % 4;
      f.data[k] = pick == 0 ? 0x00 : pick == 1 ? 0xFF : static_cast<std::uint8_t>(next());
    }
    const virt::CanFrameBits bits = virt::can_frame_bits(f);
    std::printf("%d %d %d %d %X ", f.extended ? 1 : 0, f.fd ? 1 : 0, f.brs ? 1 : 0, f.rtr ? 1 : 0, f.id);
    if (f.rtr) {
      std::printf("R%u", static_cast<unsigned>(f.len)); // remote: only the DLC matters
    } else if (f.len == 0) {
      std::printf("-");
    }
    for (std::size_t k = 0; k < f.len && !f.rtr; ++k) std::printf("%02X", f.data[k]);
    std::printf(" %u %u %u\n", bits.nominal, bits.data, bits.stuff);
  }
  return 0;
}
