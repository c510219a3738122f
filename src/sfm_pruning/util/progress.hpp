// Progress reporting. Algorithms never print; they call a ProgressCallback that the CLI turns
// into a progress bar (and tests ignore).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace sfm_pruning {

// Called with the stage name, the number of finished work items and the total.
using ProgressCallback = std::function<void(const std::string& stage, size_t done, size_t total)>;

inline void ReportProgress(const ProgressCallback& callback, const std::string& stage, size_t done,
                           size_t total) {
  if (callback) callback(stage, done, total);
}

}  // namespace sfm_pruning
