// Rendering of a synthetic layout into per-view features: what a SIFT detector would return on
// the images of the scene, with the ground truth of every keypoint.
#pragma once

#include <map>
#include <vector>

#include "sfm_pruning/eval/synthetic_descriptors.hpp"
#include "sfm_pruning/eval/synthetic_layout.hpp"
#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/landmark.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// The look of every appearance id: its descriptor histogram and its keypoint orientation.
struct AppearanceTable {
  std::vector<DescriptorHistogram> histograms;
  std::vector<float> orientations;  // radians
};

AppearanceTable MakeAppearanceTable(IndexT num_appearances, uint64_t seed);

struct RenderedViews {
  FeaturesPerView features;
  std::map<IndexT, std::vector<IndexT>> feature_landmarks;  // kUndefinedIndex for clutter
  std::map<IndexT, Landmark> landmarks;  // every detected point, even if seen once
};

// A point is detected in view i when it is within options.max_distance_m, in front of the
// camera, projects inside the image, faces the camera (angle between its normal and the ray
// below options.max_incidence_deg, unless that is >= 90) and survives dropout. Its keypoint gets
// Gaussian pixel noise (dropped if the noise moves it out of the image) and a noisy descriptor.
// Clutter keypoints with unrelated descriptors are added, and the features are shuffled so that
// their order says nothing about the truth. Views are numbered as layout.poses.
RenderedViews RenderViews(const SceneLayout& layout, const CameraIntrinsics& intrinsics,
                          const AppearanceTable& appearances, const SyntheticSceneOptions& options,
                          const ProgressCallback& progress = {});

}  // namespace sfm_pruning
