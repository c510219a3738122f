// Reader of the ground-truth camera lists shipped with the benchmark datasets (gt_cameras.txt).
//
// One camera per line, '#' starts a comment line:
//   image_name width height fx fy cx cy skew r00 r01 r02 r10 r11 r12 r20 r21 r22 tx ty tz
// R and t are world -> camera (x_cam = R X + t, the Pose::FromRotationTranslation form).
//
// Pixel convention: the numbers come from the Strecha .camera and Middlebury *_par.txt matrices,
// which OpenMVG's own quality evaluation loads unchanged; we do the same and take (cx, cy) as
// given in PruneSfM's convention (top-left pixel centre at (0, 0)). Whether the original
// calibrations meant (0.5, 0.5) is unknown; half a pixel does not affect any pose metric.
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// Returns one view per line (view id = intrinsic id = pose id = 0-based camera index in file
// order), a kPinhole intrinsic when fx == fy and kPinholeFxFy otherwise. The rotation is
// snapped to the nearest rotation matrix (the files round entries to about six digits).
// Throws Error naming the file and line for: a wrong field count, a non-number, non-positive
// size or focal, non-zero skew (not representable), a matrix that is not a rotation, a
// duplicate image name, or a file without cameras.
SfmData ReadGroundTruthCameras(const std::filesystem::path& path);

// One line per posed view, in view id order: filename width height fx fy cx cy 0 R(row-major) t,
// every number with 17 significant digits (an exact round trip). Atomic. Throws Error naming the
// file for an intrinsic the format cannot hold (distortion, spherical). Synthetic scenes ship
// their truth this way, in the same form as the real benchmarks.
void WriteGroundTruthCameras(const SfmData& data, const std::filesystem::path& path);

}  // namespace sfm_pruning
