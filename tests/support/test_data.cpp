#include "support/test_data.hpp"

#include <cstdlib>

namespace sfm_pruning::testing {
namespace fs = std::filesystem;

fs::path SharedDir() {
  const char* dir = std::getenv("PRUNESFM_SHARED_DIR");
  if (dir == nullptr || !fs::is_directory(dir)) return {};
  return fs::path(dir);
}

fs::path ScratchDir(const std::string& name) {
  const char* binary_dir = std::getenv("PRUNESFM_BINARY_DIR");
  const fs::path root = binary_dir ? fs::path(binary_dir) / "test_scratch" : fs::temp_directory_path() / "prunesfm_test_scratch";
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path TestDataDir() { return fs::path(PRUNESFM_TEST_DATA_DIR); }

}  // namespace sfm_pruning::testing
