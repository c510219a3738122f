// Synthetic scenes for the bundle adjustment, filtering and retriangulation tests: a ring of
// cameras around a box of points, two intrinsics (pinhole and radial K3), exact projections plus
// Gaussian pixel noise and planted outlier observations. Header-only: the tests/global glob
// compiles only *_test.cpp files.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "sfm_pruning/global/bundle_observations.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning::bundle_test {

struct SceneOptions {
  int num_cameras = 20;
  int num_points = 1000;
  double noise_px = 0.0;        // standard deviation per pixel coordinate
  double outlier_ratio = 0.0;   // fraction of observations displaced by outlier_error_px
  double outlier_error_px = 20.0;
  // Points fill a box of these half sizes around the origin, cameras stand on a ring of this
  // radius: points then cover most of each image, which pins the principal point down.
  Eigen::Vector3d box_half_size = Eigen::Vector3d(5.0, 5.0, 4.0);
  double ring_radius = 12.0;
  // k1, k2, k3 of intrinsic 1 (radial K3).
  std::array<double, 3> radial_distortion = {-0.08, 0.01, 0.001};
  uint32_t seed = 7;
};

// The tests' usual noisy scene: 1 px noise per coordinate and 2 % outliers at 20 px.
inline SceneOptions NoisySceneOptions(int num_points) {
  SceneOptions options;
  options.noise_px = 1.0;
  options.outlier_ratio = 0.02;
  options.num_points = num_points;
  return options;
}

struct Scene {
  SfmData truth;     // exact poses, points and intrinsics, with noisy observations
  std::set<std::pair<IndexT, IndexT>> outliers;  // (landmark id, view id)
  double radius = 0.0;  // of the camera ring: the scene's length scale
};

// World -> camera rotation of a ring camera at `azimuth` whose optical axis is tilted by
// `elevation` below the horizon (image +y points down, world +z up).
inline Eigen::Matrix3d RingRotation(double azimuth, double elevation) {
  Eigen::Matrix3d facing_minus_x;  // the camera at azimuth 0 looks along -x
  facing_minus_x << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  return Eigen::AngleAxisd(elevation, Eigen::Vector3d::UnitX()).toRotationMatrix() * facing_minus_x *
         Eigen::AngleAxisd(-azimuth, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

inline Eigen::Vector3d RandomUnitVector(std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return Eigen::Vector3d(normal(*rng), normal(*rng), normal(*rng)).normalized();
}

// Even views use intrinsic 0 (pinhole), odd views intrinsic 1 (radial K3); view id = pose id.
inline Scene MakeScene(const SceneOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  Scene scene;
  scene.radius = options.ring_radius;
  SfmData& data = scene.truth;
  data.intrinsics[0] = CameraIntrinsics::Pinhole(1000, 800, 800.0, 505.0, 395.0);
  data.intrinsics[1] = CameraIntrinsics(CameraModel::kPinholeRadialK3, 1000, 800, {900.0, 495.0, 405.0, options.radial_distortion[0], options.radial_distortion[1],
                                     options.radial_distortion[2]});
  for (int k = 0; k < options.num_cameras; ++k) {
    const double azimuth = 2.0 * M_PI * k / options.num_cameras;
    const Eigen::Vector3d center(scene.radius * std::cos(azimuth), scene.radius * std::sin(azimuth),
                                 0.3 * scene.radius * std::sin(3.0 * azimuth));
    const IndexT id = static_cast<IndexT>(k);
    View view;
    view.id_view = view.id_pose = id;
    view.id_intrinsic = id % 2;
    view.width = 1000;
    view.height = 800;
    data.views[id] = view;
    // Aimed at the origin, give or take a degree.
    const double elevation = std::atan2(center.z(), scene.radius) + DegToRad(uniform(rng));
    data.poses[id] = Pose(RingRotation(azimuth + DegToRad(uniform(rng)), elevation), center);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  IndexT landmark_id = 0;
  while (static_cast<int>(data.structure.size()) < options.num_points) {
    Landmark landmark;
    landmark.X = options.box_half_size.cwiseProduct(Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)));
    for (const auto& [view_id, view] : data.views) {
      const CameraIntrinsics& intrinsics = data.IntrinsicsOf(view);
      const Eigen::Vector3d X_cam = data.PoseOf(view).ToCamera(landmark.X);
      if (X_cam.z() <= 0.0) continue;
      Eigen::Vector2d pixel = intrinsics.Project(X_cam);
      if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > view.width - 1 || pixel.y() > view.height - 1) continue;
      pixel += options.noise_px * Eigen::Vector2d(noise(rng), noise(rng));
      if (unit(rng) < options.outlier_ratio) {
        const double angle = 2.0 * M_PI * unit(rng);
        pixel += options.outlier_error_px * Eigen::Vector2d(std::cos(angle), std::sin(angle));
        scene.outliers.insert({landmark_id, view_id});
      }
      landmark.observations[view_id] = Observation{pixel, static_cast<IndexT>(landmark.observations.size())};
    }
    if (landmark.observations.size() < 2) {
      for (const auto& [view_id, obs] : landmark.observations) scene.outliers.erase({landmark_id, view_id});
      continue;
    }
    data.structure[landmark_id++] = landmark;
  }
  return scene;
}

// Rotates every pose by ~rotation_deg about a random axis and moves every centre by
// centre_fraction of the scene radius.
inline void PerturbPoses(double rotation_deg, double center_fraction, double radius, uint32_t seed, SfmData* data) {
  std::mt19937 rng(seed);
  for (auto& [id, pose] : data->poses) {
    pose.rotation = Eigen::AngleAxisd(rotation_deg * M_PI / 180.0, RandomUnitVector(&rng)).toRotationMatrix() *
                    pose.rotation;
    pose.center += center_fraction * radius * RandomUnitVector(&rng);
  }
}

// Moves every landmark by `fraction` of the scene radius in a random direction.
inline void PerturbPoints(double fraction, double radius, uint32_t seed, SfmData* data) {
  std::mt19937 rng(seed);
  for (auto& [id, landmark] : data->structure) landmark.X += fraction * radius * RandomUnitVector(&rng);
}

// Similarity taking the estimated centres onto the true ones (Umeyama), applied to `estimate`.
inline void AlignToTruth(const SfmData& truth, SfmData* estimate) {
  Eigen::Matrix3Xd source(3, estimate->poses.size()), target(3, estimate->poses.size());
  int column = 0;
  for (const auto& [id, pose] : estimate->poses) {
    source.col(column) = pose.center;
    target.col(column++) = truth.poses.at(id).center;
  }
  const Eigen::Matrix4d T = Eigen::umeyama(source, target, true);
  const Eigen::Matrix3d sR = T.topLeftCorner<3, 3>();
  const double scale = std::cbrt(sR.determinant());
  const Eigen::Matrix3d R = sR / scale;
  for (auto& [id, pose] : estimate->poses) {
    pose.center = sR * pose.center + T.topRightCorner<3, 1>();
    pose.rotation = pose.rotation * R.transpose();
  }
  for (auto& [id, landmark] : estimate->structure) landmark.X = sR * landmark.X + T.topRightCorner<3, 1>();
}

// Per-coordinate RMS reprojection error of the observations that are not planted outliers.
inline double InlierRmsPx(const SfmData& data, const Scene& scene) {
  double sum = 0.0;
  size_t count = 0;
  for (const auto& [landmark_id, landmark] : data.structure) {
    for (const PosedObservation& obs : PosedObservationsOf(data, landmark)) {
      if (scene.outliers.count({landmark_id, obs.view_id})) continue;
      const double error = ReprojectionErrorPx(obs, landmark.X);
      sum += error * error;
      ++count;
    }
  }
  return std::sqrt(sum / (2.0 * count));
}

}  // namespace sfm_pruning::bundle_test
