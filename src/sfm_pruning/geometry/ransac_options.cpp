#include "sfm_pruning/geometry/ransac_options.hpp"

#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {

void RansacOptions::Check() const {
  // OpenGV's Ransac draws no hypothesis at all with 0 iterations, so every estimate would fail.
  RequireAtLeast(max_iterations, 1, "RansacOptions::max_iterations");
  // A probability; 1 runs all max_iterations, 0 stops after the first model.
  RequireInRange(confidence, 0.0, 1.0, "RansacOptions::confidence");
}

}  // namespace sfm_pruning
