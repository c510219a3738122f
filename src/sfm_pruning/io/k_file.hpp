// K files: a camera matrix as 9 numbers (3 rows of 3, any whitespace), as the Strecha datasets'
// K.txt. Pixel convention of the file is taken as is (OpenMVG reads these files the same way).
#pragma once

#include <filesystem>

#include <Eigen/Core>

namespace sfm_pruning {

// Throws Error naming the file when it is missing, holds another count of numbers or a
// non-number, or K is not [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0.
Eigen::Matrix3d ReadKFile(const std::filesystem::path& path);

}  // namespace sfm_pruning
