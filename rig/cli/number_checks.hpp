#pragma once
// Range checks for numeric options. CLI11's PositiveNumber says of `--lines 0` "Value 0 not in
// range 0.000000 to 1797693134862315708...": the bound is wrong (0 is excluded) and unreadable.
// These name the bound a person would write.

#include <CLI/Error.hpp> // Validators.hpp uses ValidationError without including it

#include <CLI/Validators.hpp>

namespace hilrig::cli {

// "--lines: 0 is not > 0": a finite number greater than zero.
[[nodiscard]] CLI::Validator positive_number();
// "--cpu: -1 is not >= 0": a finite number, zero or more.
[[nodiscard]] CLI::Validator non_negative_number();

} // namespace hilrig::cli
