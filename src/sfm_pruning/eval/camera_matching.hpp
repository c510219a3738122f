// Pairs the cameras of an estimated reconstruction with those of the ground truth by image file
// name. Reconstructions of the same images made by different tools number their views
// differently and may store paths relative to different roots, so the basename is the only
// identity they share.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct MatchedCamera {
  std::string name;              // image basename
  Pose ground_truth;
  std::optional<Pose> estimate;  // empty when the estimate did not register this image
};

struct CameraMatching {
  // One entry per posed ground-truth image, sorted by name (the order pairs are enumerated in).
  std::vector<MatchedCamera> cameras;
  size_t num_estimate_images = 0;        // posed views of the estimate
  size_t num_unmatched_estimate_images = 0;  // posed estimate views with no ground truth

  size_t NumRegistered() const;
};

// Matches every posed ground-truth view to the posed estimate view with the same basename.
// Throws Error when a basename occurs twice among the posed views of either side (the match
// would be ambiguous); `estimate_source` / `ground_truth_source` name the inputs in messages.
CameraMatching MatchCamerasByName(const SfmData& estimate, const SfmData& ground_truth,
                                  const std::string& estimate_source = "estimate",
                                  const std::string& ground_truth_source = "ground truth");

}  // namespace sfm_pruning
