// Exact synthetic scenes for the positioning tests: cameras around a point cloud, each looking at
// the origin, observations obtained by projecting the true points through a pinhole or a radial
// camera (CameraIntrinsics::Project), so Unproject has to undo real distortion. The view graph
// carries the matches of every pair with enough common points and the true relative poses.
// Header-only: each positioning_*_test.cpp includes it (the test glob compiles *_test.cpp only).
#pragma once

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning::testing {

struct PositioningSceneOptions {
  int num_cameras = 30;
  int num_points = 800;
  double visibility = 0.6;      // probability that a camera observes a point it could see
  double pixel_noise_std = 0.0;
  double outlier_ratio = 0.0;   // observations moved to a uniformly random pixel
  size_t min_pair_matches = 20;
  uint64_t seed = 1;
};

// The small scene of the determinism and progress tests (20 cameras, 500 points).
inline PositioningSceneOptions SmallSceneOptions() {
  PositioningSceneOptions options;
  options.num_cameras = 20;
  options.num_points = 500;
  return options;
}

struct PositioningScene {
  SfmData sfm_data;  // views (ids 10, 12, ...), two intrinsics; no poses, no structure
  FeaturesPerView features;
  ViewGraph graph;                             // true relative poses, |t| = 1
  std::map<IndexT, Pose> true_poses;           // by view id
  std::map<IndexT, Eigen::Matrix3d> rotations;  // exact
  std::vector<Eigen::Vector3d> points;
  std::map<std::pair<IndexT, IndexT>, bool> is_outlier;  // (view, feature) -> corrupted
};

inline Pose LookAtOrigin(const Eigen::Vector3d& center, const Eigen::Vector3d& up_hint) {
  const Eigen::Vector3d z = (-center).normalized();
  const Eigen::Vector3d x = up_hint.cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;  // rows: camera axes in world coordinates
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return Pose(R, center);
}

inline PositioningScene MakePositioningScene(const PositioningSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> uniform01(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, options.pixel_noise_std > 0.0 ? options.pixel_noise_std : 1.0);

  PositioningScene scene;
  scene.sfm_data.intrinsics[0] = CameraIntrinsics::Pinhole(1000, 750, 900.0, 499.5, 374.5);
  scene.sfm_data.intrinsics[1] =
      CameraIntrinsics(CameraModel::kPinholeRadialK3, 1000, 750, {1100.0, 505.0, 370.0, -0.08, 0.02, 0.0});

  for (int k = 0; k < options.num_points; ++k) {
    const double x = unit(rng), y = unit(rng), z = unit(rng);
    scene.points.emplace_back(2.0 * x, 2.0 * y, 2.0 * z);
  }
  std::vector<IndexT> view_ids;
  for (int c = 0; c < options.num_cameras; ++c) {
    Eigen::Vector3d direction;
    do {
      const double x = unit(rng), y = unit(rng), z = unit(rng);
      direction = Eigen::Vector3d(x, y, 0.6 * z);
    } while (direction.norm() < 0.2);
    const double distance = 7.0 + 3.0 * uniform01(rng);
    const Eigen::Vector3d up(0.1 * unit(rng), 0.1 * unit(rng), 1.0);
    const IndexT view_id = static_cast<IndexT>(10 + 2 * c);
    View view;
    view.id_view = view_id;
    view.id_intrinsic = static_cast<IndexT>(c % 2);
    view.id_pose = view_id + 1000;
    view.width = 1000;
    view.height = 750;
    scene.sfm_data.views[view_id] = view;
    scene.true_poses[view_id] = LookAtOrigin(distance * direction.normalized(), up);
    scene.rotations[view_id] = scene.true_poses[view_id].rotation;
    view_ids.push_back(view_id);
  }

  // feature_of[view][point] = feature index, for the pairwise matches below.
  std::map<IndexT, std::map<int, IndexT>> feature_of;
  for (const IndexT view_id : view_ids) {
    const Pose& pose = scene.true_poses[view_id];
    const CameraIntrinsics& camera = scene.sfm_data.intrinsics.at(scene.sfm_data.views[view_id].id_intrinsic);
    FeatureSet& features = scene.features[view_id];
    for (int k = 0; k < options.num_points; ++k) {
      if (uniform01(rng) > options.visibility) continue;
      const Eigen::Vector3d X_cam = pose.ToCamera(scene.points[k]);
      if (X_cam.z() <= 0.0) continue;
      Eigen::Vector2d pixel = camera.Project(X_cam);
      if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > camera.width() - 1 || pixel.y() > camera.height() - 1) continue;
      const IndexT feature_id = static_cast<IndexT>(features.keypoints.size());
      const bool outlier = uniform01(rng) < options.outlier_ratio;
      if (outlier) {
        pixel = Eigen::Vector2d(uniform01(rng) * (camera.width() - 1), uniform01(rng) * (camera.height() - 1));
      } else if (options.pixel_noise_std > 0.0) {
        const double dx = noise(rng), dy = noise(rng);
        pixel += Eigen::Vector2d(dx, dy);
      }
      scene.is_outlier[{view_id, feature_id}] = outlier;
      Keypoint keypoint;
      keypoint.x = static_cast<float>(pixel.x());
      keypoint.y = static_cast<float>(pixel.y());
      features.keypoints.push_back(keypoint);
      feature_of[view_id][k] = feature_id;
    }
  }

  for (size_t a = 0; a < view_ids.size(); ++a) {
    scene.graph.AddNode(view_ids[a]);
    for (size_t b = a + 1; b < view_ids.size(); ++b) {
      std::vector<FeatureMatch> matches;
      for (const auto& [point, feature_a] : feature_of[view_ids[a]]) {
        const auto feature_b = feature_of[view_ids[b]].find(point);
        if (feature_b != feature_of[view_ids[b]].end()) matches.push_back({feature_a, feature_b->second});
      }
      if (matches.size() < options.min_pair_matches) continue;
      RelativePose relative =
          RelativePoseBetween(scene.true_poses[view_ids[a]], scene.true_poses[view_ids[b]]);
      relative.translation.normalize();
      scene.graph.AddEdge(view_ids[a], view_ids[b], matches, relative);
    }
  }
  return scene;
}

// How the angular filter sorted the observations: what the scene corrupted vs what was written.
struct KeptObservations {
  size_t num_outliers = 0;
  size_t num_inliers = 0;
  size_t num_outliers_kept = 0;
  size_t num_inliers_kept = 0;
};

inline KeptObservations CountKeptObservations(const PositioningScene& scene, const SfmData& estimate) {
  KeptObservations counts;
  for (const auto& [key, outlier] : scene.is_outlier) ++(outlier ? counts.num_outliers : counts.num_inliers);
  for (const auto& [landmark_id, landmark] : estimate.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      ++(scene.is_outlier.at({view_id, observation.id_feat}) ? counts.num_outliers_kept : counts.num_inliers_kept);
    }
  }
  return counts;
}

// Camera-centre error after the best alignment. The rotations are exact and held fixed by both
// methods, so the estimate differs from the truth by a scale and a translation only (no
// rotation): c_true ~ s c + t, solved in closed form by least squares. Returns the largest
// aligned centre error divided by the RMS distance of the true centres to their centroid.
inline double MaxRelativeCenterError(const std::map<IndexT, Pose>& true_poses, const SfmData& estimate) {
  std::vector<Eigen::Vector3d> truth, estimated;
  for (const auto& [view_id, view] : estimate.views) {
    const auto pose = estimate.poses.find(view.id_pose);
    if (pose == estimate.poses.end()) continue;
    truth.push_back(true_poses.at(view_id).center);
    estimated.push_back(pose->second.center);
  }
  if (truth.size() < 2) return INFINITY;
  Eigen::Vector3d mean_truth = Eigen::Vector3d::Zero(), mean_estimated = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < truth.size(); ++k) {
    mean_truth += truth[k] / static_cast<double>(truth.size());
    mean_estimated += estimated[k] / static_cast<double>(truth.size());
  }
  double cross = 0.0, spread_estimated = 0.0, spread_truth = 0.0;
  for (size_t k = 0; k < truth.size(); ++k) {
    cross += (estimated[k] - mean_estimated).dot(truth[k] - mean_truth);
    spread_estimated += (estimated[k] - mean_estimated).squaredNorm();
    spread_truth += (truth[k] - mean_truth).squaredNorm();
  }
  const double scale = cross / spread_estimated;
  const double scene_radius = std::sqrt(spread_truth / static_cast<double>(truth.size()));
  double max_error = 0.0;
  for (size_t k = 0; k < truth.size(); ++k) {
    const Eigen::Vector3d aligned = scale * (estimated[k] - mean_estimated) + mean_truth;
    max_error = std::max(max_error, (aligned - truth[k]).norm() / scene_radius);
  }
  return max_error;
}

}  // namespace sfm_pruning::testing
