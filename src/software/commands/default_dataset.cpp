#include "software/commands/default_dataset.hpp"

#include <cstdlib>
#include <vector>

namespace prunesfm {
namespace fs = std::filesystem;

std::optional<fs::path> FindDefaultDataset() {
  std::vector<fs::path> shared_dirs;
  if (const char* env = std::getenv("PRUNESFM_SHARED_DIR"); env != nullptr && *env != '\0') {
    shared_dirs.emplace_back(env);
  }
#ifdef PRUNESFM_SOURCE_DIR
  shared_dirs.push_back(fs::path(PRUNESFM_SOURCE_DIR).parent_path() / "shared");
#endif
  std::error_code ec;
  for (fs::path start : {fs::current_path(ec), fs::read_symlink("/proc/self/exe", ec)}) {
    for (fs::path dir = start; !dir.empty(); dir = dir.parent_path()) {
      shared_dirs.push_back(dir / "shared");
      if (dir == dir.root_path()) break;
    }
  }
  for (const fs::path& shared : shared_dirs) {
    const fs::path images = shared / kDefaultDatasetRelative;
    if (fs::is_directory(images, ec)) return images.lexically_normal();
  }
  return std::nullopt;
}

}  // namespace prunesfm
