// Helpers shared by the OpenMVG feature and match tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::openmvg_features_test {

// A hand-made golden file of tests/data/openmvg_features.
inline std::filesystem::path Golden(const std::string& name) {
  return testing::TestDataDir() / "openmvg_features" / name;
}

// Runs `call`, expects an Error, and returns its message.
template <typename Call>
std::string ErrorMessage(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected sfm_pruning::Error";
  return {};
}

inline void WriteText(const std::filesystem::path& path, const std::string& text) {
  WriteFileAtomically(path, false, [&](std::ostream& out) { out << text; });
}

}  // namespace sfm_pruning::openmvg_features_test
