#pragma once
// A file replaced atomically: written to "<path>.tmp", fsynced, then renamed over path, so a
// crash leaves either the previous complete file or the new one, never half a file. On any
// failure (ENOSPC, EFBIG, EIO) the temporary is removed and std::runtime_error names the file
// and the errno text.

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
