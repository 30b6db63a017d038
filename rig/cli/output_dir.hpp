#pragma once
// `hilrig run --out DIR`: one campaign at a time writes a directory, and what it leaves there
// is this campaign's evidence only.
//
// The directory is locked with flock() on DIR/.hilrig.lock for the whole run (released when
// the process ends, however it ends): a second run on the same DIR is refused (OutputBusy,
// exit 3: the rig cannot run it now; nothing in DIR is touched). A directory holding a file
// hilrig does not write, or a DIR that is a file (or under one), is refused before anything
// runs (ForeignOutput, exit 2: choose another --out); otherwise every earlier campaign's evidence is removed
// (results.json, junit.xml, report.html, runs.jsonl, trace*.vcd, can.log, *.gtkw and their *.tmp), so no
// trace or CAN log of an earlier campaign is mistaken for this one's.

#include <filesystem>
#include <stdexcept>

#include "rig/cli/directory_lock.hpp"
#include "rig/cli/run_evidence.hpp"

namespace hilrig::cli {

class OutputBusy : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};
class ForeignOutput : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class OutputDirectory {
public:
  // Creates dir, takes its lock and clears the evidence of an earlier campaign; throws
  // OutputBusy or ForeignOutput as above, std::runtime_error with the errno text otherwise.
  explicit OutputDirectory(const std::filesystem::path& dir);

private:
  DirectoryLock lock_;
};

} // namespace hilrig::cli
