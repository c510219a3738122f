// A reconstruction seen through undistorted pinhole cameras, and its undistorted images.
#pragma once

#include <filesystem>

#include "sfm_pruning/export/undistortion.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Every intrinsic replaced by UndistortedIntrinsics and every observation moved to where the
// undistorted image shows it; views, poses, 3D points, colours and ids unchanged. Throws Error for
// a spherical camera.
SfmData UndistortModel(const SfmData& data, const UndistortOptions& options = {});

struct ImageWriteOptions {
  int num_threads = 1;
  int jpeg_quality = 95;  // for outputs named *.jpg / *.jpeg
};

// Writes the undistorted image of every posed view to output_dir / view.RelativeImagePath(),
// reading the original from image_root / the same path; the file type follows the name. Views
// whose camera has no distortion (undistorted camera = original) are copied byte for byte.
// Images are processed in parallel with progress "undistorting images". Throws Error naming the
// image when it is missing, does not decode, or its size differs from its camera's.
void WriteUndistortedImages(const SfmData& original, const SfmData& undistorted,
                            const std::filesystem::path& image_root, const std::filesystem::path& output_dir,
                            const ImageWriteOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
