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
//
// A suite's OUT is taken the same way for the whole suite, but holds the campaigns' own
// directories (OUT/<name>/, each taken and cleared when its campaign runs): there a
// subdirectory is not foreign, and the files of a single campaign run there earlier
// (results.json, runs.jsonl, trace.vcd, ...) are removed as any earlier evidence is.

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
  // What the directory holds: one campaign's files, or a suite's (its junit.xml and index
  // report.html beside a directory per campaign).
  enum class Holds { Campaign, Suite };
  // Creates dir, takes its lock and clears the evidence of an earlier campaign; throws
  // OutputBusy or ForeignOutput as above, std::runtime_error with the errno text otherwise.
  explicit OutputDirectory(const std::filesystem::path& dir, Holds holds = Holds::Campaign);

private:
  DirectoryLock lock_;
};

} // namespace hilrig::cli
