#pragma once
// The Series 2700 adapter: the virtual 2700 (models/pls2700) as a campaign's DUT. Pins SIN1,
// COS1, SIN2, COS2 (analog stators), IN1, IN2 (2742-18), OUT1..OUT8. Parameter "model" picks
// one of the seven modules ("2731" ... "2742-18"); variants by the model's fault names.
//
// Host words (no handshake; a block transfer is a buffer plus a length). A campaign's
// `write = [n, w1, ..., wn]` is one BTW of n words: the rig writes words 1.. first and
// word 0 last, so the length arrives when the words are in place.
//   output word  0      writing n (1..64) sends words 1..n as one BTW
//   output words 1..64  the BTW being assembled (its word 1 = the first instruction word)
//   input words  0..4   the BTR (1-channel modules: 0..2, then 0)
//   input word   5      the programming error byte
//   input word   6      the single-transfer position word (2731-04)

#include "models/pls2700/model_variant.hpp"
#include "models/pls2700/params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

inline constexpr std::size_t kPls2700BtwSendWord = 0;
inline constexpr std::size_t kPls2700ErrorWord = 5;
inline constexpr std::size_t kPls2700SingleTransferWord = 6;

// The registry entry (name "pls2700").
[[nodiscard]] DutInfo pls2700_info();

// The module and the model's Params from a full set of this entry's parameters (defaults
// filled in): what a campaign's [dut.params] and `hilrig serve pls2700 --param` set.
[[nodiscard]] models::pls2700::ModelVariant pls2700_model(const DutParams& params);
[[nodiscard]] models::pls2700::Params pls2700_params(const DutParams& params);

} // namespace hilrig::duts
