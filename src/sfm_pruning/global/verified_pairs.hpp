// Pairs whose inlier matches were verified elsewhere (e.g. COLMAP's two_view_geometries), the
// input of BuildViewGraphFromVerifiedPairs. Independent of any file format: the CLI fills it from
// io/colmap_database.hpp.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct VerifiedPair {
  // FeatureMatch::i in ViewPair::first, j in ViewPair::second.
  std::vector<FeatureMatch> inliers;
  // Camera first -> camera second; absent when the source did not store one (COLMAP 3.8 writes
  // zeros unless asked), in which case the builder re-estimates it from the inliers.
  std::optional<RelativePose> relative_pose;
};

using VerifiedPairs = std::map<ViewPair, VerifiedPair>;

}  // namespace sfm_pruning
