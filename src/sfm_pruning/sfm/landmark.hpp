// Landmarks (3D points) and their observations; control points use the same type.
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include <Eigen/Core>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct Observation {
  Eigen::Vector2d x = Eigen::Vector2d::Zero();  // raw (distorted) pixel position of the feature
  IndexT id_feat = kUndefinedIndex;             // index of the feature in its view's feature file
  bool operator==(const Observation& o) const { return x == o.x && id_feat == o.id_feat; }
};

struct Landmark {
  Eigen::Vector3d X = Eigen::Vector3d::Zero();  // world coordinates
  std::map<IndexT, Observation> observations;   // keyed by view id (not pose id)
  // Not part of OpenMVG's format; carried for COLMAP models and coloured PLY.
  std::array<uint8_t, 3> color = {128, 128, 128};
  double error = -1.0;  // mean reprojection error in pixels, -1 when unknown (COLMAP's ERROR)

  // Geometry and observations only: colour and error are display data.
  bool operator==(const Landmark& o) const { return X == o.X && observations == o.observations; }
};

}  // namespace sfm_pruning
