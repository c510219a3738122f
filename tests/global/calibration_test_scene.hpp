// A synthetic scene for the focal calibration tests, at the level of features: cameras in front of
// a box of points, each aimed at its own point of the box (so that the optical axes do not meet
// in one point, which would leave the focal undetermined), exact projections plus pixel noise.
// Feature index = landmark index in every view; the matches of a pair are the landmarks both
// views see. Header-only: the tests/global glob compiles only *_test.cpp files.
#pragma once

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning::calibration_test {

struct SceneOptions {
  int num_views = 12;
  int num_points = 600;
  double noise_px = 0.5;
  // Even views use intrinsic 0 (focal_px), odd views intrinsic 1 (second_focal_px) when it is > 0;
  // otherwise every view uses intrinsic 0.
  double focal_px = 1000.0;
  double second_focal_px = 0.0;
  // Aim every camera at the box centre instead (the degenerate configuration).
  bool common_target = false;
  uint32_t seed = 11;
};

struct Scene {
  SfmData truth;  // views, intrinsics, poses, landmarks (observations name feature = landmark ids)
  FeaturesPerView features;
  PairwiseMatches matches;
};

// World -> camera rotation of a camera at `center` looking at `target`, image y roughly down
// (world -y up), rolled by `roll` radians.
inline Eigen::Matrix3d LookAt(const Eigen::Vector3d& center, const Eigen::Vector3d& target, double roll) {
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d(0.0, 1.0, 0.0).cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x;
  R.row(1) = y;
  R.row(2) = z;
  return Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix() * R;
}

inline Scene MakeScene(const SceneOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, options.noise_px);
  constexpr uint32_t kWidth = 1024, kHeight = 768;
  Scene scene;
  SfmData& truth = scene.truth;
  truth.intrinsics[0] = CameraIntrinsics::Pinhole(kWidth, kHeight, options.focal_px, 511.5, 383.5);
  const bool two_cameras = options.second_focal_px > 0.0;
  if (two_cameras) truth.intrinsics[1] = CameraIntrinsics::Pinhole(kWidth, kHeight, options.second_focal_px, 511.5, 383.5);
  for (int k = 0; k < options.num_points; ++k) {
    Landmark landmark;
    landmark.X = Eigen::Vector3d(3.0 * uniform(rng), 3.0 * uniform(rng), 1.5 * uniform(rng));
    truth.structure[static_cast<IndexT>(k)] = landmark;
  }
  for (int k = 0; k < options.num_views; ++k) {
    const IndexT id = static_cast<IndexT>(k);
    View view;
    view.id_view = view.id_pose = id;
    view.id_intrinsic = two_cameras ? id % 2 : 0;
    view.width = kWidth;
    view.height = kHeight;
    view.filename = "view" + std::to_string(k) + ".png";
    truth.views[id] = view;
    const Eigen::Vector3d center(4.0 * uniform(rng), 2.0 * uniform(rng), -10.0 + uniform(rng));
    const Eigen::Vector3d target = options.common_target
                                       ? Eigen::Vector3d::Zero()
                                       : Eigen::Vector3d(1.5 * uniform(rng), 1.5 * uniform(rng), uniform(rng));
    truth.poses[id] = Pose(LookAt(center, target, 0.3 * uniform(rng)), center);
  }
  // Every view gets a keypoint per landmark (feature index = landmark id); those outside the image
  // are kept as features but never matched.
  std::map<IndexT, std::vector<bool>> visible;
  for (const auto& [view_id, view] : truth.views) {
    FeatureSet& features = scene.features[view_id];
    std::vector<bool>& seen = visible[view_id];
    for (auto& [landmark_id, landmark] : truth.structure) {
      const Eigen::Vector3d X_cam = truth.PoseOf(view).ToCamera(landmark.X);
      Eigen::Vector2d pixel = X_cam.z() > 0.0 ? truth.IntrinsicsOf(view).Project(X_cam) : Eigen::Vector2d(-1, -1);
      const bool inside = pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() <= kWidth - 1 && pixel.y() <= kHeight - 1;
      pixel += Eigen::Vector2d(noise(rng), noise(rng));
      features.keypoints.push_back({static_cast<float>(pixel.x()), static_cast<float>(pixel.y()), 2.f, 0.f});
      seen.push_back(inside);
      if (inside) landmark.observations[view_id] = Observation{pixel, landmark_id};
    }
  }
  for (const auto& [a, seen_a] : visible) {
    for (const auto& [b, seen_b] : visible) {
      if (b <= a) continue;
      std::vector<FeatureMatch> matches;
      for (size_t k = 0; k < seen_a.size(); ++k) {
        if (seen_a[k] && seen_b[k]) matches.push_back({static_cast<IndexT>(k), static_cast<IndexT>(k)});
      }
      if (matches.size() >= 30) scene.matches[{a, b}] = std::move(matches);
    }
  }
  return scene;
}

// The scene's views and intrinsics without poses or structure, every focal times `factor`.
inline SfmData ListingWithFocalOff(const Scene& scene, double factor) {
  SfmData listing = scene.truth;
  listing.poses.clear();
  listing.structure.clear();
  for (auto& [id, intrinsics] : listing.intrinsics) intrinsics.SetFocalLength(intrinsics.FocalLength() * factor);
  return listing;
}

}  // namespace sfm_pruning::calibration_test
