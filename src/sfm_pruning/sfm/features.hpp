// Per-view features: keypoints (position, scale, orientation) and 128-byte SIFT-like
// descriptors. Feature index = row index, as in OpenMVG's .feat/.desc files.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct Keypoint {
  float x = 0.f;  // pixel, OpenMVG convention (top-left pixel centre at 0, 0)
  float y = 0.f;
  float scale = 1.f;
  float orientation = 0.f;  // radians
};

inline constexpr int kDescriptorSize = 128;
using Descriptor = std::array<uint8_t, kDescriptorSize>;

struct FeatureSet {
  std::vector<Keypoint> keypoints;
  std::vector<Descriptor> descriptors;  // empty, or one per keypoint

  size_t size() const { return keypoints.size(); }
  Eigen::Vector2d Position(size_t i) const { return {keypoints[i].x, keypoints[i].y}; }
};

// Features of every view, keyed by view id.
using FeaturesPerView = std::map<IndexT, FeatureSet>;

}  // namespace sfm_pruning
