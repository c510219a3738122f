// A reconstruction seen through undistorted pinhole cameras, and its undistorted images.
#pragma once

#include <filesystem>
#include <map>

#include "sfm_pruning/export/undistortion.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Where the image of an undistorted view comes from: a view of the original model, seen through
// `rotation` (original camera frame -> this view's frame; identity but for cube faces).
struct UndistortedViewSource {
  IndexT view = kUndefinedIndex;
  int cube_face = -1;  // 0..5 for the faces of a spherical view
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

struct UndistortedModel {
  SfmData data;
  std::map<IndexT, UndistortedViewSource> sources;  // one per view of `data`
};

// The model through pinhole cameras (UndistortedIntrinsics): every observation moved to where the
// undistorted image shows it; ids, poses, 3D points and colours unchanged. A posed spherical view
// becomes six cube-face views (new view and pose ids after the largest existing ones, in view and
// face order; images "<name>_<face>.<ext>", each observation in the face its ray falls in); an
// unposed spherical view is dropped with its observations.
UndistortedModel UndistortModel(const SfmData& data, const UndistortOptions& options = {});

struct ImageWriteOptions {
  int num_threads = 1;
  int jpeg_quality = 95;  // for outputs named *.jpg / *.jpeg

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Writes the image of every posed view of `undistorted` to output_dir / its relative path, resampled
// from its source image (image_root / the original view's path); the file type follows the name.
// Views whose camera equals the original's are copied byte for byte. Images are processed in
// parallel with progress "undistorting images". Throws Error naming the image when it is missing,
// does not decode, or its size differs from its camera's.
void WriteUndistortedImages(const SfmData& original, const UndistortedModel& undistorted,
                            const std::filesystem::path& image_root, const std::filesystem::path& output_dir,
                            const ImageWriteOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
