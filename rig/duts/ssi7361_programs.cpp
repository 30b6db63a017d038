// The 7361's instruction set in its manual's words (docs/spec/ssi7361.md §4-§5; manual
// seeds/004, Lnnn): one `setup` block sets the %Q command bits of the groups given and their
// %AQ words (Format %AQ1, Scalars %AQ2-3, Preset %AQ4-5 low word first, RUT %AQ6; L2080-L2123),
// written up to the last word a group uses. The Format word is written whole, so code, logic
// and clock left out keep what the campaign's last Format write set (the board cannot be
// read back; factory binary, positive, 125 kHz before any, L2159-L2161).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "models/ssi7361/programming.hpp"
#include "rig/duts/device_programs.hpp"

namespace hilrig::duts {
namespace {

using Words = std::vector<std::uint16_t>;
using Opt = std::optional<std::int64_t>;
constexpr std::int64_t kMaxPreset = 33'554'431; // 25-bit data values (L91, L148)

struct Setup {
  Opt bits;      // N, %AQ1 bits 05-01
  Opt first_bit; // M, %AQ1 bits 13-09
  Opt code;      // 0 binary, 1 gray (bit 07)
  Opt logic;     // 0 positive, 1 negative (bit 08)
  Opt clock;     // 0 125 kHz, 1 500 kHz (bit 16)
  Opt multiplier;
  Opt divisor;
  Opt preset;
  Opt rate_update_ms;
  Opt count_direction; // 0 positive, 1 negative
  bool apply_preset = false;
  bool eeprom_clear = false;
};

// %AQ1 bits 07 (Gray), 08 (Negative) and 16 (500 kHz): the Format's settings a setup may leave out.
constexpr std::uint16_t kKeptFormatBits = 0x80C0;

// Those bits as the last earlier write the board took that programmed the Format (%Q bit 02) set
// them; 0, the factory setup (L2159-L2161), before any. Each earlier write is replayed as the
// board's own programming cycle (run_cycle) on the words written so far, so a Format it refused
// (FMTErr, or ignored behind a pending error) sets nothing. A device fault or power cycle
// between the writes is not seen here.
std::uint16_t kept_format_bits(duts::EarlierWrites earlier) {
  namespace m = models::ssi7361;
  m::ProgramState state;
  m::CommandWords image{};
  std::uint16_t kept = 0;
  for (const std::vector<std::uint16_t>& write : earlier) {
    std::copy_n(write.begin(), std::min(write.size(), image.size()), image.begin());
    if (m::run_cycle(state, image, 0, m::Params{}).accepted && (image[0] & bit(1)) != 0)
      kept = static_cast<std::uint16_t>(image[1] & kKeptFormatBits);
  }
  return kept;
}

Words setup(const Setup& s, duts::EarlierWrites earlier) {
  const bool format = s.bits || s.first_bit;
  if (format && !(s.bits && s.first_bit))
    throw ProgramFieldError(s.bits ? "first_bit" : "bits",
                            "bits and first_bit together: the Format word needs both");
  if (!format && (s.code || s.logic || s.clock))
    throw ProgramFieldError(s.code    ? "code"
                            : s.logic ? "logic"
                                      : "clock",
                            "with bits and first_bit: part of the Format word (L2126-L2152)");
  if (format && *s.first_bit + *s.bits > models::ssi7361::kMaxMsbPlusBits) // the board's own rule (setup.hpp)
    throw ProgramFieldError("bits",
                            "first_bit + bits <= 26: the field within the 25-bit frame (L2162-L2163)");
  if (s.multiplier.has_value() != s.divisor.has_value())
    throw ProgramFieldError(s.multiplier ? "divisor" : "multiplier",
                            "multiplier and divisor together (Scalars)");
  if (s.multiplier && *s.multiplier > *s.divisor)
    throw ProgramFieldError("multiplier", "a multiplier <= the divisor (L1192-L1194)");
  std::uint16_t q = static_cast<std::uint16_t>(bit(14, s.eeprom_clear) | bit(0, s.apply_preset));
  Words w(7, 0);
  std::size_t last = 0;
  if (format) {
    q |= bit(1);
    const std::uint16_t kept = kept_format_bits(earlier);
    const auto setting = [&](const Opt& given, unsigned n) {
      return given ? bit(n, *given == 1) : static_cast<std::uint16_t>(kept & bit(n));
    };
    w[1] = static_cast<std::uint16_t>(setting(s.clock, 15) | (*s.first_bit << 8) | setting(s.logic, 7) |
                                      setting(s.code, 6) | *s.bits);
    last = 1;
  }
  if (s.multiplier) {
    q |= bit(2);
    w[2] = word(*s.multiplier);
    w[3] = word(*s.divisor);
    last = 3;
  }
  if (s.preset) {
    q |= bit(3);
    w[4] = word(*s.preset & 0xFFFF);
    w[5] = word((*s.preset >> 16) & 0xFFFF);
    last = 5;
  }
  if (s.rate_update_ms) {
    q |= bit(4);
    w[6] = word(*s.rate_update_ms);
    last = 6;
  }
  if (s.count_direction) q |= static_cast<std::uint16_t>(bit(5) | bit(6, *s.count_direction == 1));
  if (q == 0)
    throw ProgramFieldError("apply_preset",
                            "at least one instruction: a group, apply_preset or eeprom_clear");
  w[0] = q;
  w.resize(last + 1);
  return w;
}

} // namespace

std::vector<ProgramBlockInfo> ssi7361_programs() {
  return {
      program_block<Setup>(
          "setup", "the SSI setup and host instructions of one programming cycle (L2080-L2123)",
          {
              {"bits", &Setup::bits,
               "Format: Number of Data Bits N (%AQ1 bits 05-01); only with first_bit (the Format word is "
               "written whole)",
               2, 25},
              {"first_bit", &Setup::first_bit,
               "Format: MSB Number M (%AQ1 bits 13-09); only with bits, first_bit + bits <= 26", 1, 24},
              {"code",
               &Setup::code,
               "Format: the data's code (bit 07); only with bits and first_bit (absent: as the last Format "
               "written)",
               0,
               0,
               {"binary", "gray"}},
              {"logic",
               &Setup::logic,
               "Format: the data's logic (bit 08); only with bits and first_bit (absent: as the last Format "
               "written)",
               0,
               0,
               {"positive", "negative"}},
              {"clock",
               &Setup::clock,
               "Format: the SSI clock (bit 16); only with bits and first_bit (absent: as the last Format "
               "written)",
               0,
               0,
               {"125kHz", "500kHz"}},
              {"multiplier", &Setup::multiplier,
               "Scalars: Scalar Multiplier (%AQ2); only with divisor, at most it (L1192-L1194)", 1, 32767},
              {"divisor", &Setup::divisor, "Scalars: Scalar Divisor (%AQ3); only with multiplier", 1, 32767},
              {"preset", &Setup::preset, "Preset Value (%AQ4 low, %AQ5 high)", -kMaxPreset, kMaxPreset},
              {"rate_update_ms", &Setup::rate_update_ms, "Rate Update Time, ms (%AQ6)", 1, 1000},
              {"count_direction",
               &Setup::count_direction,
               "Count Direction (PgmDir with CntDir)",
               0,
               0,
               {"positive", "negative"}},
              {"apply_preset", &Setup::apply_preset,
               "AplyPst: the Data Value becomes the Preset Value (L1224)"},
              {"eeprom_clear", &Setup::eeprom_clear, "E2CLR: clear an EEPROM error (%Q 15)"},
          },
          &setup),
  };
}

} // namespace hilrig::duts
