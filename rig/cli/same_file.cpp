#include "rig/cli/same_file.hpp"

namespace hilrig::cli {

namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) {
    const bool same = fs::equivalent(a, b, ec);
    if (!ec) return same;
  }
  const auto resolved = [](const fs::path& p) {
    std::error_code e;
    const fs::path r = fs::weakly_canonical(fs::absolute(p), e);
    return e ? fs::absolute(p).lexically_normal() : r;
  };
  return resolved(a) == resolved(b);
}

} // namespace hilrig::cli
