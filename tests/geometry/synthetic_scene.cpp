#include "geometry/synthetic_scene.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace sfm_pruning::testing {
namespace {

double Uniform(std::mt19937* rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(*rng);
}

bool InsideImage(const CameraIntrinsics& intrinsics, const Eigen::Vector2d& pixel) {
  return pixel.x() >= 0.0 && pixel.y() >= 0.0 && pixel.x() <= intrinsics.width() - 1.0 &&
         pixel.y() <= intrinsics.height() - 1.0;
}

}  // namespace

Eigen::Matrix3d RandomRotation(std::mt19937* rng, double max_angle_rad) {
  Eigen::Vector3d axis(Uniform(rng, -1, 1), Uniform(rng, -1, 1), Uniform(rng, -1, 1));
  while (axis.norm() < 1e-3) axis = Eigen::Vector3d(Uniform(rng, -1, 1), Uniform(rng, -1, 1), Uniform(rng, -1, 1));
  return Eigen::AngleAxisd(Uniform(rng, 0.0, max_angle_rad), axis.normalized()).toRotationMatrix();
}

Pose LookAtPose(const Eigen::Vector3d& center, const Eigen::Vector3d& target, double roll_rad) {
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d x = z.unitOrthogonal();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return Pose(Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() * R, center);
}

CameraIntrinsics RandomIntrinsics(std::mt19937* rng, bool distortion) {
  const double focal = Uniform(rng, 600.0, 1200.0);
  std::vector<double> params = {focal, 500.0 + Uniform(rng, -20, 20), 375.0 + Uniform(rng, -20, 20), 0.0, 0.0, 0.0};
  if (distortion) {
    params[3] = Uniform(rng, -0.1, 0.1);
    params[4] = Uniform(rng, -0.02, 0.02);
    params[5] = Uniform(rng, -0.005, 0.005);
  }
  return CameraIntrinsics(CameraModel::kPinholeRadialK3, 1000, 750, params);
}

SyntheticScene MakeSyntheticScene(int num_cameras, const SyntheticViewOptions& options) {
  std::mt19937 rng(options.seed);
  SyntheticScene scene;
  for (int c = 0; c < num_cameras; ++c) {
    // Centres on a sphere cap in front of the box (+z side), so the views overlap.
    const Eigen::Vector3d direction =
        Eigen::Vector3d(Uniform(&rng, -0.4, 0.4), Uniform(&rng, -0.4, 0.4), -1.0).normalized();
    const Eigen::Vector3d target(Uniform(&rng, -0.3, 0.3), Uniform(&rng, -0.3, 0.3), Uniform(&rng, -0.3, 0.3));
    scene.poses.push_back(LookAtPose(Uniform(&rng, 6.0, 10.0) * direction, target, Uniform(&rng, -M_PI, M_PI)));
    scene.intrinsics.push_back(RandomIntrinsics(&rng, options.distortion));
  }
  scene.pixels.resize(num_cameras);
  scene.bearings.resize(num_cameras);
  std::normal_distribution<double> noise(0.0, options.pixel_noise_std);
  while (static_cast<int>(scene.points.size()) < options.num_points) {
    const Eigen::Vector3d X(Uniform(&rng, -2, 2), Uniform(&rng, -2, 2), Uniform(&rng, -2, 2));
    std::vector<Eigen::Vector2d> pixels;
    for (int c = 0; c < num_cameras; ++c) {
      const Eigen::Vector3d X_cam = scene.poses[c].ToCamera(X);
      if (X_cam.z() <= 0.1) break;
      const Eigen::Vector2d pixel = scene.intrinsics[c].Project(X_cam);
      if (!InsideImage(scene.intrinsics[c], pixel)) break;
      pixels.push_back(pixel);
    }
    if (static_cast<int>(pixels.size()) != num_cameras) continue;
    const bool outlier = Uniform(&rng, 0.0, 1.0) < options.outlier_ratio;
    if (outlier) {
      pixels.back() = Eigen::Vector2d(Uniform(&rng, 0, 999), Uniform(&rng, 0, 749));
    }
    for (int c = 0; c < num_cameras; ++c) {
      if (options.pixel_noise_std > 0.0) pixels[c] += Eigen::Vector2d(noise(rng), noise(rng));
      scene.pixels[c].push_back(pixels[c]);
      scene.bearings[c].push_back(scene.intrinsics[c].Unproject(pixels[c]));
    }
    scene.points.push_back(X);
    scene.is_outlier.push_back(outlier);
  }
  return scene;
}

RelativePose TrueRelativePose(const SyntheticScene& scene) {
  RelativePose truth = RelativePoseBetween(scene.poses[0], scene.poses[1]);
  truth.translation.normalize();
  return truth;
}

}  // namespace sfm_pruning::testing
