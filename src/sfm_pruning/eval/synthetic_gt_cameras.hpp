// Writer of the datasets' ground-truth camera list (gt_cameras.txt, /work/shared/datasets/README.md),
// so synthetic scenes ship their truth in the same form as the real benchmarks. The reader is
// io/ground_truth_cameras.hpp; see there for the line layout and conventions.
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// One line per posed view, in view id order: filename width height fx fy cx cy 0 R(row-major) t,
// every number with 17 significant digits (an exact round trip). Atomic. Throws Error naming the
// file for an intrinsic the format cannot hold (distortion, spherical).
void WriteGroundTruthCameras(const SfmData& data, const std::filesystem::path& path);

}  // namespace sfm_pruning
