// A small scene with real image files: cameras around a cloud of points, each image rendered
// from a smooth colour function of the world ray through each pixel, so that any pinhole or
// distorted view of the scene has a known expected colour at every pixel.
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning::testing {

// The colour (B, G, R in [0, 255]) seen along a world direction (need not be normalized).
cv::Vec3d ColorOfRay(const Eigen::Vector3d& world_direction);

// Renders the view `view_id` of `data` (its camera, pose and size) as an 8-bit BGR image.
cv::Mat RenderView(const SfmData& data, IndexT view_id);

// Three posed views of one `camera` (whose size sets the images'), 40 landmarks observed where
// they project (id_feat = landmark index), images "view<i>.png" in root_path = `image_dir`,
// rendered and written there.
SfmData MakeRenderedScene(const CameraIntrinsics& camera, const std::filesystem::path& image_dir);

}  // namespace sfm_pruning::testing
