// Exact synthetic scenes for the geometry tests: random points in a box around the origin,
// random cameras looking at it, random intrinsics (with distortion), bearings obtained through
// CameraIntrinsics::Project / Unproject exactly as real features would be.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning::testing {

// A rotation about a uniformly random axis by an angle uniform in [0, max_angle_rad].
Eigen::Matrix3d RandomRotation(std::mt19937* rng, double max_angle_rad);

// A camera at `center` looking at `target`, rolled by `roll_rad` about its optical axis.
Pose LookAtPose(const Eigen::Vector3d& center, const Eigen::Vector3d& target, double roll_rad);

// Radial-K3 intrinsics, 1000 x 750, focal in [600, 1200], principal point near the centre;
// small random distortion when `distortion` is set.
CameraIntrinsics RandomIntrinsics(std::mt19937* rng, bool distortion);

struct SyntheticViewOptions {
  int num_points = 200;
  double pixel_noise_std = 0.0;  // Gaussian noise added to each pixel coordinate
  double outlier_ratio = 0.0;    // fraction of correspondences replaced by random pixels
  bool distortion = true;
  uint32_t seed = 1;
};

// One observation set: correspondence k relates points[k] to pixels/bearings in each camera.
struct SyntheticScene {
  std::vector<Pose> poses;
  std::vector<CameraIntrinsics> intrinsics;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<Eigen::Vector2d>> pixels;     // [camera][k]
  std::vector<std::vector<Eigen::Vector3d>> bearings;   // [camera][k], from the noisy pixels
  std::vector<bool> is_outlier;                         // per correspondence
};

// `num_cameras` cameras 6-10 units from the origin, all seeing every point (points that fall
// outside an image are redrawn). Outliers replace the pixel in the last camera only.
SyntheticScene MakeSyntheticScene(int num_cameras, const SyntheticViewOptions& options);

// Ground truth camera 0 -> camera 1 from the scene's absolute poses, with |t| = 1 as the relative
// pose estimators return it.
RelativePose TrueRelativePose(const SyntheticScene& scene);

}  // namespace sfm_pruning::testing
