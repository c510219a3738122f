#include "support/test_data.hpp"

#include <cstdlib>

namespace sfm_pruning::testing {
namespace fs = std::filesystem;

// PRUNESFM_SHARED_DIR in the environment overrides the folder configured at build time.
fs::path SharedDir() {
  const char* from_environment = std::getenv("PRUNESFM_SHARED_DIR");
  const fs::path dir = from_environment ? fs::path(from_environment) : fs::path(PRUNESFM_DEFAULT_SHARED_DIR);
  if (!fs::is_directory(dir)) return {};
  return fs::weakly_canonical(dir);
}

fs::path ScratchDir(const std::string& name) {
  const fs::path dir = fs::path(PRUNESFM_TEST_SCRATCH_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path TestDataDir() { return fs::path(PRUNESFM_TEST_DATA_DIR); }

}  // namespace sfm_pruning::testing
