#include "models/pls2700/instructions.hpp"

#include <array>
#include <bit>
#include <optional>

#include "models/pls2700/bcd.hpp"
#include "models/pls2700/error_codes.hpp"

namespace hilrig::models::pls2700 {
namespace {

// A BCD field in range lo..hi, or nothing (invalid nibbles count as out of range [X]).
std::optional<int> bcd_in(std::uint16_t word, int lo, int hi) {
  const std::optional<int> v = from_bcd(word);
  if (!v || *v < lo || *v > hi) {
    return std::nullopt;
  }
  return v;
}

std::uint8_t channel_code(std::uint8_t ch1_code, int channel) {
  return static_cast<std::uint8_t>(ch1_code + (channel == 1 ? error::kChannel2 : 0));
}

void erase_channel_setpoints(const ModelTraits& model, Setup& setup, int channel) {
  for (int out = 1; out <= kOutputCount; ++out) {
    if (owner_channel(model, setup, out) == channel) {
      setup.outputs[static_cast<std::size_t>(out - 1)].pair_count = 0;
    }
  }
}

InstructionResult setup_instruction(std::span<const std::uint16_t> words, const ModelTraits& model,
                                    Setup& setup) {
  InstructionResult r{InstructionKind::Setup, 0, 1};
  const std::uint16_t cmd = words[0];
  const unsigned high = cmd >> 8;
  const unsigned x = (cmd >> 4) & 0xFu;
  const unsigned y = cmd & 0xFu;
  std::array<int, 2> chans{0, 1};
  std::size_t nchan = 1;
  if (high == 0x98) {
    chans[0] = 1;
  } else if (high == 0xA8) {
    nchan = 2;
  }
  const bool uses_ch2 = high != 0x88;
  const unsigned max_y = model.has_inputs ? 0xFu : 0x7u;
  // Non-existent channel: "a programming error code" (L1350), model 21h.
  if ((uses_ch2 && model.channels == 1) || x != 0 || y == 0 || y > max_y) {
    r.error = error::kInvalidCommand;
    return r;
  }
  const std::size_t needed = static_cast<std::size_t>(std::popcount(y)) * nchan;
  if (words.size() < 1 + needed) {
    r.error = error::kInvalidLength;
    r.length = words.size();
    return r;
  }
  r.length = 1 + needed;

  // Stage every field in data order: SF1 SF2, CO1 CO2, TR1 TR2, CL1 CL2.
  struct Staged {
    std::optional<int> sf, co, tr, cl, oa;
    std::optional<Trigger> trigger;
  };
  std::array<Staged, 2> st{};
  std::size_t at = 1;
  const auto next = [&] { return words[at++]; };
  if (y & kSetupSf) {
    for (std::size_t k = 0; k < nchan; ++k) {
      const int ch = chans[k];
      st[static_cast<std::size_t>(ch)].sf = bcd_in(next(), 2, model.max_scale_factor);
      if (!st[static_cast<std::size_t>(ch)].sf) {
        r.error = channel_code(error::kInvalidSf1, ch);
        return r;
      }
    }
  }
  const auto new_sf = [&](int ch) {
    const Staged& s = st[static_cast<std::size_t>(ch)];
    return s.sf ? *s.sf : setup.channels[static_cast<std::size_t>(ch)].scale_factor;
  };
  if (y & kSetupCo) {
    for (std::size_t k = 0; k < nchan; ++k) {
      const int ch = chans[k];
      st[static_cast<std::size_t>(ch)].co = bcd_in(next(), 0, new_sf(ch) - 1);
      if (!st[static_cast<std::size_t>(ch)].co) {
        r.error = channel_code(error::kInvalidCo1, ch);
        return r;
      }
    }
  }
  if (y & kSetupTr) {
    for (std::size_t k = 0; k < nchan; ++k) {
      const int ch = chans[k];
      Staged& s = st[static_cast<std::size_t>(ch)];
      const std::uint16_t word = next();
      const auto low = static_cast<std::uint16_t>(word & 0xFFu);
      const auto upper = static_cast<std::uint16_t>(word >> 8);
      // Low byte (tach code) is checked before the high byte [I].
      s.tr = bcd_in(low, 0, 4);
      if (!s.tr) {
        r.error = channel_code(error::kInvalidTr1, ch);
        return r;
      }
      if (model.has_inputs) {
        const std::optional<int> ipot = bcd_in(upper, 0, 3);
        if (!ipot) {
          r.error = channel_code(error::kInvalidIpOt1, ch);
          return r;
        }
        s.trigger = static_cast<Trigger>(*ipot);
      } else if (model.channels == 2 && ch == 0) {
        s.oa = bcd_in(upper, 0, 8); // R-OA-3
        if (!s.oa) {
          r.error = error::kInvalidOa;
          return r;
        }
      } // 1-channel, or channel 2: high byte ignored [X]
    }
  }
  if (y & kSetupCl) {
    for (std::size_t k = 0; k < nchan; ++k) {
      const int ch = chans[k];
      st[static_cast<std::size_t>(ch)].cl = bcd_in(next(), 1, new_sf(ch));
      if (!st[static_cast<std::size_t>(ch)].cl) {
        r.error = channel_code(error::kInvalidCl1, ch);
        return r;
      }
    }
  }

  // Apply: per channel SF first (with its side effects), then CO, TR, CL.
  for (std::size_t k = 0; k < nchan; ++k) {
    const int ch = chans[k];
    const Staged& s = st[static_cast<std::size_t>(ch)];
    ChannelSetup& c = setup.channels[static_cast<std::size_t>(ch)];
    if (s.sf) {
      c.scale_factor = *s.sf;
      c.circular_offset = 0; // R-SF-2
      if (model.has_inputs) {
        c.cycle_length = *s.sf;
        erase_channel_setpoints(model, setup, ch);
      }
    }
    if (s.co) {
      c.circular_offset = *s.co;
    }
    if (s.tr) {
      c.tach_code = *s.tr;
    }
    if (s.trigger) {
      c.trigger = *s.trigger;
    }
    if (s.oa) {
      setup.output_allocation = *s.oa;
    }
    if (s.cl) {
      c.cycle_length = *s.cl;
      erase_channel_setpoints(model, setup, ch);
    }
  }
  return r;
}

InstructionResult limit_instruction(std::span<const std::uint16_t> words, const ModelTraits& model,
                                    const InstructionRules& rules, Setup& setup) {
  InstructionResult r{InstructionKind::LimitSwitch, 0, 1};
  const unsigned x = (words[0] >> 4) & 0xFu;
  const unsigned y = words[0] & 0xFu;
  if (x < 1 || x > 8) {
    r.error = error::invalid_ls(x);
    return r;
  }
  if (y < 1 || y > 8) {
    r.error = error::invalid_sp(y);
    return r;
  }
  const int output = static_cast<int>(x);
  const int pairs = static_cast<int>(y);
  const std::size_t needed = 1 + 2 * static_cast<std::size_t>(pairs);
  if (words.size() < 1 + needed) {
    r.error = error::kInvalidLength;
    r.length = words.size();
    return r;
  }
  r.length = 1 + needed;

  OutputSetup staged = setup.outputs[static_cast<std::size_t>(output - 1)];
  const bool has_advances = output <= model.advance_outputs;
  const std::uint16_t adv = words[1];
  const std::optional<int> a_on = bcd_in(static_cast<std::uint16_t>(adv >> 8), 0, kMaxAdvanceMs);
  if (!a_on || (!has_advances && *a_on != 0)) {
    r.error = error::invalid_on_advance(output);
    return r;
  }
  const std::optional<int> a_off = bcd_in(static_cast<std::uint16_t>(adv & 0xFFu), 0, kMaxAdvanceMs);
  if (!a_off || (!has_advances && *a_off != 0) || (rules.enforce_off_le_on && *a_off > *a_on)) {
    r.error = error::invalid_off_advance(output);
    return r;
  }
  staged.advance_on_ms = *a_on;
  staged.advance_off_ms = *a_off;

  const int ch = owner_channel(model, setup, output);
  const ChannelSetup& c = setup.channels[static_cast<std::size_t>(ch)];
  // Setpoints are MP counts 0..SF-1; on the 2742-18 LS counts 0..CL-1 with ON <= OFF.
  const int limit = model.has_inputs ? c.cycle_length : c.scale_factor;
  for (int k = 0; k < pairs; ++k) {
    const std::optional<int> on = bcd_in(words[2 + 2 * static_cast<std::size_t>(k)], 0, limit - 1);
    if (!on) {
      r.error = error::invalid_on(output);
      return r;
    }
    const std::optional<int> off = bcd_in(words[3 + 2 * static_cast<std::size_t>(k)], 0, limit - 1);
    if (!off || (model.has_inputs && *on > *off)) {
      r.error = error::invalid_off(output);
      return r;
    }
    staged.pairs[static_cast<std::size_t>(k)] = SetpointPair{*on, *off};
  }
  staged.pair_count = pairs; // R-LS-6: the instruction replaces the whole pair list
  for (int k = pairs; k < kMaxPairs; ++k) {
    staged.pairs[static_cast<std::size_t>(k)] = SetpointPair{};
  }
  setup.outputs[static_cast<std::size_t>(output - 1)] = staged;
  r.output = output;
  return r;
}

} // namespace

int owner_channel(const ModelTraits& model, const Setup& setup, int output) {
  if (model.channels == 1) {
    return 0;
  }
  if (model.has_inputs) {
    return output <= 4 ? 0 : 1; // fixed on the 2742-18 (L1486)
  }
  return output <= setup.output_allocation ? 0 : 1;
}

InstructionResult execute_instruction(std::span<const std::uint16_t> words, const ModelTraits& model,
                                      const InstructionRules& rules, Setup& setup) {
  const std::uint16_t cmd = words[0];
  switch (cmd >> 8) {
  case 0x81:
  case 0x82:
  case 0x84:
    if ((cmd & 0xFFu) != 0) {
      break;
    }
    if (cmd == kDisableKeyboard) {
      setup.keyboard_disabled = true;
      return {InstructionKind::DisableKeyboard, 0, 1};
    }
    if (cmd == kEnableKeyboard) {
      setup.keyboard_disabled = false;
      return {InstructionKind::EnableKeyboard, 0, 1};
    }
    return {InstructionKind::ClearErrors, 0, 1};
  case 0x83:
    setup.mask = static_cast<std::uint8_t>(cmd & 0xFFu); // binary, bit 0 = output 1 (R-M-1)
    return {InstructionKind::SetMask, 0, 1};
  case 0x88:
  case 0x98:
  case 0xA8:
    return setup_instruction(words, model, setup);
  case 0xC0:
    return limit_instruction(words, model, rules, setup);
  default:
    break;
  }
  return {InstructionKind::Invalid, error::kInvalidCommand, 1};
}

} // namespace hilrig::models::pls2700
