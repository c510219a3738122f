// Ceres cost functions of the bundle adjustment: one residual block per observation.
//
// Parameter blocks (in this order):
//   pose       7  unit quaternion (w, x, y, z) of the world -> camera rotation (pose.hpp's R),
//                 then the camera centre in world coordinates (pose.hpp's c)
//   point      3  landmark in world coordinates
//   intrinsics N  CameraIntrinsics::params in camera_models.hpp's layout (pinhole family only)
// We optimise (R, c) rather than (R, t) so that the block maps one-to-one onto our Pose and a
// gauge on a centre is a plain coordinate (bundle_pose_manifold.hpp). Rotation and centre share
// one block because the Schur complement's cost grows with the square of the camera blocks a
// landmark touches.
//
// Jacobians are analytic up to the camera model: with X_cam = R (X - c),
//   d X_cam / d theta = -[X_cam]x   (PoseManifold's tangent: R <- Exp(theta) R),
//   d X_cam / d c     = -R,
//   d X_cam / d X     =  R,
// and the projection's derivatives with respect to X_cam and the intrinsics come from Ceres jets
// of 3 + N values through camera_models::ProjectPinhole, so each model's maths exists once. The
// pose Jacobian is written in PoseManifold's convention: the 6 tangent columns in stored
// columns 0-2 and 4-6, column 3 zero. (Autodiff through the quaternion, 14-value jets, was the
// largest part of each iteration.)
//
// Pinhole-family cameras: residual = projected pixel - observed pixel (px). The camera model is
// a runtime value, so the cost stores it and the block size N is a template argument chosen by
// the factory below.
// Spherical cameras: their projection is not differentiable across the image seam, so the
// residual lives on the unit sphere instead: (X_cam / |X_cam| - observed bearing) scaled by the
// camera's pixels per radian. For small errors its norm is the angular error in pixels, so the
// same Huber scale applies to both residual types.
#pragma once

#include <cmath>

#include <ceres/jet.h>
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/camera_models.hpp"

namespace sfm_pruning::bundle {

// X_cam = R (X - c) of a pose block and a point, with R kept for the Jacobians.
struct CameraFramePoint {
  Eigen::Matrix3d R;
  Eigen::Vector3d X_cam;
};

inline CameraFramePoint ToCameraFrame(const double* pose, const double* point) {
  CameraFramePoint result;
  result.R = Eigen::Quaterniond(pose[0], pose[1], pose[2], pose[3]).toRotationMatrix();
  result.X_cam = result.R * (Eigen::Map<const Eigen::Vector3d>(point) - Eigen::Map<const Eigen::Vector3d>(pose + 4));
  return result;
}

// Writes the pose and point Jacobians of a residual of kRows rows, given dr / dX_cam.
template <int kRows>
void WritePoseAndPointJacobians(const Eigen::Matrix<double, kRows, 3>& dr_dX_cam, const CameraFramePoint& frame,
                                double** jacobians) {
  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, kRows, 7, Eigen::RowMajor>> J_pose(jacobians[0]);
    Eigen::Matrix3d minus_skew;  // -[X_cam]x
    const Eigen::Vector3d& p = frame.X_cam;
    minus_skew << 0.0, p.z(), -p.y(), -p.z(), 0.0, p.x(), p.y(), -p.x(), 0.0;
    J_pose.template leftCols<3>() = dr_dX_cam * minus_skew;
    J_pose.col(3).setZero();
    J_pose.template rightCols<3>() = -dr_dX_cam * frame.R;
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, kRows, 3, Eigen::RowMajor>> J_point(jacobians[1]);
    J_point = dr_dX_cam * frame.R;
  }
}

template <int kNumIntrinsicParams>
class PinholeReprojectionCost final : public ceres::SizedCostFunction<2, 7, 3, kNumIntrinsicParams> {
 public:
  PinholeReprojectionCost(CameraModel model, const Eigen::Vector2d& observed_px)
      : model_(model), observed_px_(observed_px) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const CameraFramePoint frame = ToCameraFrame(parameters[0], parameters[1]);
    const double* intrinsics = parameters[2];
    if (jacobians == nullptr) {
      double pixel[2];
      camera_models::ProjectPinhole(model_, intrinsics, frame.X_cam.data(), pixel);
      residuals[0] = pixel[0] - observed_px_.x();
      residuals[1] = pixel[1] - observed_px_.y();
      return true;
    }
    // Derivative slots: 0-2 the camera-frame point, 3.. the intrinsics.
    using Jet = ceres::Jet<double, 3 + kNumIntrinsicParams>;
    Jet X_cam[3];
    Jet params[kNumIntrinsicParams];
    for (int k = 0; k < 3; ++k) X_cam[k] = Jet(frame.X_cam[k], k);
    for (int k = 0; k < kNumIntrinsicParams; ++k) params[k] = Jet(intrinsics[k], 3 + k);
    Jet pixel[2];
    camera_models::ProjectPinhole(model_, params, X_cam, pixel);
    residuals[0] = pixel[0].a - observed_px_.x();
    residuals[1] = pixel[1].a - observed_px_.y();
    Eigen::Matrix<double, 2, 3> dr_dX_cam;
    for (int r = 0; r < 2; ++r) dr_dX_cam.row(r) = pixel[r].v.template head<3>().transpose();
    WritePoseAndPointJacobians<2>(dr_dX_cam, frame, jacobians);
    if (jacobians[2] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, 2, kNumIntrinsicParams, Eigen::RowMajor>> J_intrinsics(jacobians[2]);
      for (int r = 0; r < 2; ++r) J_intrinsics.row(r) = pixel[r].v.template tail<kNumIntrinsicParams>().transpose();
    }
    return true;
  }

 private:
  CameraModel model_;
  Eigen::Vector2d observed_px_;
};

class SphericalBearingCost final : public ceres::SizedCostFunction<3, 7, 3> {
 public:
  SphericalBearingCost(const Eigen::Vector3d& observed_bearing, double pixels_per_radian)
      : observed_bearing_(observed_bearing.normalized()), pixels_per_radian_(pixels_per_radian) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const CameraFramePoint frame = ToCameraFrame(parameters[0], parameters[1]);
    // The epsilon keeps the norm differentiable for a point at the camera centre.
    const double norm = std::sqrt(frame.X_cam.squaredNorm() + 1e-30);
    const Eigen::Vector3d bearing = frame.X_cam / norm;
    Eigen::Map<Eigen::Vector3d> residual(residuals);
    residual = pixels_per_radian_ * (bearing - observed_bearing_);
    if (jacobians == nullptr) return true;
    // d(X / |X|) / dX = (I - b b^T) / |X|.
    const Eigen::Matrix3d dr_dX_cam =
        (pixels_per_radian_ / norm) * (Eigen::Matrix3d::Identity() - bearing * bearing.transpose());
    WritePoseAndPointJacobians<3>(dr_dX_cam, frame, jacobians);
    return true;
  }

 private:
  Eigen::Vector3d observed_bearing_;
  double pixels_per_radian_;
};

// Residual size of an observation made by a camera of `model`.
inline int ResidualSize(CameraModel model) { return IsPinholeFamily(model) ? 2 : 3; }

// The cost of one pinhole-family observation, with the intrinsics block sized for the model.
// Returns nullptr for a spherical camera (use CreateSphericalCost).
inline ceres::CostFunction* CreatePinholeCost(CameraModel model, const Eigen::Vector2d& observed_px) {
  switch (NumCameraParams(model)) {
    case 3: return new PinholeReprojectionCost<3>(model, observed_px);
    case 4: return new PinholeReprojectionCost<4>(model, observed_px);
    case 6: return new PinholeReprojectionCost<6>(model, observed_px);
    case 7: return new PinholeReprojectionCost<7>(model, observed_px);
    case 8: return new PinholeReprojectionCost<8>(model, observed_px);
    default: return nullptr;
  }
}

// The cost of one observation made by a spherical camera (pixel -> bearing through
// CameraIntrinsics::Unproject, which is fixed for this model: it has no parameters).
inline ceres::CostFunction* CreateSphericalCost(const CameraIntrinsics& intrinsics, const Eigen::Vector2d& observed_px) {
  return new SphericalBearingCost(intrinsics.Unproject(observed_px), intrinsics.FocalLength());
}

}  // namespace sfm_pruning::bundle
