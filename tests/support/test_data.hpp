// Helpers shared by all tests: where the shared data lives, and scratch directories.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace sfm_pruning::testing {

// The ../shared folder (datasets, format samples), from PRUNESFM_SHARED_DIR; empty when absent.
std::filesystem::path SharedDir();

// A fresh empty directory under the build tree, unique per test; removed at the next call
// with the same name.
std::filesystem::path ScratchDir(const std::string& name);

// Directory with the golden files committed under tests/data.
std::filesystem::path TestDataDir();

}  // namespace sfm_pruning::testing

// Skips the current test with a message when `relative` (a path below ../shared) is missing.
#define PRUNESFM_REQUIRE_SHARED(relative, out_path)                                          \
  const std::filesystem::path out_path = ::sfm_pruning::testing::SharedDir() / (relative);   \
  if (::sfm_pruning::testing::SharedDir().empty() || !std::filesystem::exists(out_path)) {   \
    GTEST_SKIP() << "shared data not available: " << (relative);                             \
  }
