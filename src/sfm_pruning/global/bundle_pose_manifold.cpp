#include "sfm_pruning/global/bundle_pose_manifold.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace sfm_pruning::bundle {
namespace {

Eigen::Quaterniond StoredRotation(const double* x) { return Eigen::Quaterniond(x[0], x[1], x[2], x[3]); }

// The rotation by the rotation vector w.
Eigen::Quaterniond Exp(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()).normalized();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle));
}

}  // namespace

bool PoseManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  const Eigen::Quaterniond rotated =
      (Exp(Eigen::Vector3d(delta[0], delta[1], delta[2])) * StoredRotation(x)).normalized();
  x_plus_delta[0] = rotated.w();
  x_plus_delta[1] = rotated.x();
  x_plus_delta[2] = rotated.y();
  x_plus_delta[3] = rotated.z();
  for (int k = 0; k < 3; ++k) x_plus_delta[4 + k] = x[4 + k] + (k == fixed_centre_axis_ ? 0.0 : delta[3 + k]);
  return true;
}

bool PoseManifold::PlusJacobian(const double* /*x*/, double* jacobian) const {
  std::fill(jacobian, jacobian + 7 * 6, 0.0);  // row-major 7 x 6
  for (int k = 0; k < 3; ++k) {
    jacobian[k * 6 + k] = 1.0;
    if (k != fixed_centre_axis_) jacobian[(4 + k) * 6 + 3 + k] = 1.0;
  }
  return true;
}

bool PoseManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  const Eigen::AngleAxisd difference(StoredRotation(y) * StoredRotation(x).conjugate());
  const Eigen::Vector3d w = difference.angle() * difference.axis();
  for (int k = 0; k < 3; ++k) {
    y_minus_x[k] = w[k];
    y_minus_x[3 + k] = k == fixed_centre_axis_ ? 0.0 : y[4 + k] - x[4 + k];
  }
  return true;
}

bool PoseManifold::MinusJacobian(const double* /*x*/, double* jacobian) const {
  std::fill(jacobian, jacobian + 6 * 7, 0.0);  // row-major 6 x 7: the transpose of PlusJacobian
  for (int k = 0; k < 3; ++k) {
    jacobian[k * 7 + k] = 1.0;
    if (k != fixed_centre_axis_) jacobian[(3 + k) * 7 + 4 + k] = 1.0;
  }
  return true;
}

}  // namespace sfm_pruning::bundle
