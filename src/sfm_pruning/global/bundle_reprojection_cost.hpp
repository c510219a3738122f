// Ceres cost functions of the bundle adjustment: one residual block per observation.
//
// Parameter blocks (in this order):
//   pose       7  unit quaternion (w, x, y, z) of the world -> camera rotation (pose.hpp's R),
//                 then the camera centre in world coordinates (pose.hpp's c)
//   point      3  landmark in world coordinates
//   intrinsics N  CameraIntrinsics::params in camera_models.hpp's layout (pinhole family only)
// We optimise (R, c) rather than (R, t) so that the block maps one-to-one onto our Pose and a
// gauge on a centre is a SubsetManifold inside the pose's product manifold. Rotation and centre
// share one block because the Schur complement's cost grows with the square of the camera
// blocks a landmark touches: two blocks per pose made it about three times the work.
//
// Pinhole-family cameras: residual = projected pixel - observed pixel (px), computed by
// camera_models::ProjectPinhole so the distortion maths exists once. The camera model is a
// runtime value, so the functor stores it and the block size N is a template argument chosen by
// the factory below.
// Spherical cameras: their projection is not differentiable across the image seam, so the
// residual lives on the unit sphere instead: (X_cam / |X_cam| - observed bearing) scaled by the
// camera's pixels per radian. For small errors its norm is the angular error in pixels, so the
// same Huber scale applies to both residual types.
#pragma once

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

#include <Eigen/Core>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/camera_models.hpp"

namespace sfm_pruning::bundle {

// World point -> camera frame with the pose block (quaternion, then centre).
template <typename T>
void WorldToCamera(const T* pose, const T* point, T* X_cam) {
  const T* center = pose + 4;
  const T offset[3] = {point[0] - center[0], point[1] - center[1], point[2] - center[2]};
  ceres::UnitQuaternionRotatePoint(pose, offset, X_cam);
}

template <int kNumIntrinsicParams>
class PinholeReprojectionCost {
 public:
  PinholeReprojectionCost(CameraModel model, const Eigen::Vector2d& observed_px)
      : model_(model), observed_px_(observed_px) {}

  template <typename T>
  bool operator()(const T* pose, const T* point, const T* intrinsics, T* residual) const {
    T X_cam[3];
    WorldToCamera(pose, point, X_cam);
    T pixel[2];
    camera_models::ProjectPinhole(model_, intrinsics, X_cam, pixel);
    residual[0] = pixel[0] - T(observed_px_.x());
    residual[1] = pixel[1] - T(observed_px_.y());
    return true;
  }

 private:
  CameraModel model_;
  Eigen::Vector2d observed_px_;
};

class SphericalBearingCost {
 public:
  SphericalBearingCost(const Eigen::Vector3d& observed_bearing, double pixels_per_radian)
      : observed_bearing_(observed_bearing.normalized()), pixels_per_radian_(pixels_per_radian) {}

  template <typename T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    T X_cam[3];
    WorldToCamera(pose, point, X_cam);
    // The epsilon keeps the norm differentiable for a point at the camera centre.
    const T norm = ceres::sqrt(X_cam[0] * X_cam[0] + X_cam[1] * X_cam[1] + X_cam[2] * X_cam[2] + T(1e-30));
    for (int k = 0; k < 3; ++k) {
      residual[k] = T(pixels_per_radian_) * (X_cam[k] / norm - T(observed_bearing_[k]));
    }
    return true;
  }

 private:
  Eigen::Vector3d observed_bearing_;
  double pixels_per_radian_;
};

// Residual size of an observation made by a camera of `model`.
inline int ResidualSize(CameraModel model) { return IsPinholeFamily(model) ? 2 : 3; }

template <int kNumIntrinsicParams>
ceres::CostFunction* CreatePinholeCostSized(CameraModel model, const Eigen::Vector2d& observed_px) {
  using Cost = PinholeReprojectionCost<kNumIntrinsicParams>;
  return new ceres::AutoDiffCostFunction<Cost, 2, 7, 3, kNumIntrinsicParams>(new Cost(model, observed_px));
}

// The cost of one pinhole-family observation, with the intrinsics block sized for the model.
// Returns nullptr for a spherical camera (use CreateSphericalCost).
inline ceres::CostFunction* CreatePinholeCost(CameraModel model, const Eigen::Vector2d& observed_px) {
  switch (NumCameraParams(model)) {
    case 3: return CreatePinholeCostSized<3>(model, observed_px);
    case 4: return CreatePinholeCostSized<4>(model, observed_px);
    case 6: return CreatePinholeCostSized<6>(model, observed_px);
    case 7: return CreatePinholeCostSized<7>(model, observed_px);
    case 8: return CreatePinholeCostSized<8>(model, observed_px);
    default: return nullptr;
  }
}

// The cost of one observation made by a spherical camera (pixel -> bearing through
// CameraIntrinsics::Unproject, which is fixed for this model: it has no parameters).
inline ceres::CostFunction* CreateSphericalCost(const CameraIntrinsics& intrinsics, const Eigen::Vector2d& observed_px) {
  return new ceres::AutoDiffCostFunction<SphericalBearingCost, 3, 7, 3>(
      new SphericalBearingCost(intrinsics.Unproject(observed_px), intrinsics.FocalLength()));
}

}  // namespace sfm_pruning::bundle
