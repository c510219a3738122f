// The RANSAC controls shared by every sampling estimator of this module.
#pragma once

#include <cstdint>

namespace sfm_pruning {

struct RansacOptions {
  // Stop at this many hypotheses, or earlier once `confidence` is reached (adaptive count).
  int max_iterations = 1000;
  // Probability of having drawn at least one outlier-free sample when stopping early.
  double confidence = 0.999;
  // Seed of the sampler: same input + same seed = same output, bitwise.
  uint64_t seed = 0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

}  // namespace sfm_pruning
