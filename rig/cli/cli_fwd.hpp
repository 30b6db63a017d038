#pragma once
// The CLI11 types a command's header names, declared only: a file that includes the header (a
// test, another command) does not compile CLI11's ~20,000 lines (about 8 s of compiler time per
// file). The command's own .cpp includes <CLI/CLI.hpp>.

namespace CLI {
class App;
class Option;
} // namespace CLI
