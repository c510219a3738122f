// A 3-D similarity transform (scale, rotation, translation) between two world frames: the gauge
// freedom of a reconstruction. Used to align an estimate onto the ground truth (eval) and to
// relate the frames of two independently solved subgraphs (pruning).
#pragma once

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

// X' = scale * rotation * X + translation.
struct Similarity3 {
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& X) const { return scale * rotation * X + translation; }
  // The same camera expressed in the transformed world: centre moved with the world, and
  // world' -> camera = (world -> camera) * rotation^T.
  Pose Apply(const Pose& pose) const { return Pose(pose.rotation * rotation.transpose(), Apply(pose.center)); }

  // (this ∘ other)(X) = this(other(X)).
  Similarity3 Compose(const Similarity3& other) const {
    Similarity3 composed;
    composed.scale = scale * other.scale;
    composed.rotation = rotation * other.rotation;
    composed.translation = scale * rotation * other.translation + translation;
    return composed;
  }

  Similarity3 Inverse() const {
    Similarity3 inverse;
    inverse.scale = 1.0 / scale;
    inverse.rotation = rotation.transpose();
    inverse.translation = -inverse.scale * (inverse.rotation * translation);
    return inverse;
  }
};

}  // namespace sfm_pruning
