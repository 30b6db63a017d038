#pragma once
// Whether two paths name one file, however they are spelt: a command that writes a file
// refuses one that is also its input (`merge`, `trend`), and an input given twice.

#include <filesystem>

namespace hilrig::cli {

// The same file when both exist (a hard link, a symbolic link, "a/../a": same device and
// inode), else the same path once the links and dots of its existing part resolve.
[[nodiscard]] bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace hilrig::cli
