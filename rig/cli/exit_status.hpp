#pragma once
// How a subcommand ends the program with a status: hilrig's exit codes are part of its
// interface (0 all passed, 1 a check failed, 2 bad input, 3 a rig fault).

#include <CLI/Error.hpp>
#include <stdexcept>

namespace hilrig::cli {

enum ExitStatus : int { kPassed = 0, kCheckFailed = 1, kBadInput = 2, kRigFault = 3 };

// An output the command could not write (a full disk, a file size limit): the rig's failure,
// 3, as `hilrig run` exits for it, not bad input.
struct WriteFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown from a subcommand's callback; main() returns the code.
[[noreturn]] inline void exit_with(int code) { throw CLI::RuntimeError(code); }

} // namespace hilrig::cli
