#pragma once
// A file replaced atomically: written to "<path>.tmp", then renamed over path, so a crash of
// hilrig leaves either the previous complete file or the new one, never half a file. On any
// failure (ENOSPC, EFBIG, EIO) the temporary is removed and std::runtime_error names the file
// and the errno text.
// Not fsynced: the rename alone gives the crash-safety above (the kernel holds the written
// pages; a process crash cannot tear them), and an fsync per file was a tenth of a short
// campaign's CPU (docs/PERFORMANCE.md, "Fixed cost of a run"). What a power loss must not
// lose is the run log (rig/results/run_log.hpp), which syncs every record: results.json,
// junit.xml and report.html are folded from it (`hilrig merge`), and a trace is a rerun away
// (same inputs and seed, same bytes).

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace hilrig::rig {

void write_file_atomically(const std::filesystem::path& path, const std::string& text);
// The same, streamed: `write` formats into an ostream over the temporary with a 1 MiB buffer,
// so a file of hundreds of MB (a long run's trace.vcd) is never held in memory whole.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);
// `link` becomes the same file as `target` (written before, complete): a hard link, made at
// "<link>.tmp" and renamed over link, or a copy where the file system refuses links.
void link_file_atomically(const std::filesystem::path& target, const std::filesystem::path& link);

} // namespace hilrig::rig
