// toml++'s compiled part (its "compiled library" mode: TOML_HEADER_ONLY=0 everywhere, the
// implementation in exactly one translation unit), built into hilrig instead of loaded from
// libtomlplusplus.so.3: the process floor of a short `hilrig run` (docs/PERFORMANCE.md,
// "Fixed cost of a run"). Compiled with the same configuration macros as every user of
// <toml++/toml.h> (deps/CMakeLists.txt), so the ABI namespaces match.

#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
