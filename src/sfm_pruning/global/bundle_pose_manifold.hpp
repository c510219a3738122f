// The manifold of a bundle-adjustment pose block: 7 stored values (unit quaternion w, x, y, z of
// the world -> camera rotation, then the camera centre), 6 tangent values (a rotation vector
// applied on the camera side, R <- Exp(d_theta) R, then a centre offset, c <- c + d_c).
//
// Why our own instead of Ceres' QuaternionManifold x EuclideanManifold<3>: the reprojection
// costs (bundle_reprojection_cost.hpp) write their Jacobians with respect to this tangent
// directly, which is cheap in closed form (dX_cam / d_theta = -[X_cam]x), instead of with respect
// to the 4 quaternion values, which autodiff made the most expensive part of every iteration.
// Ceres forms J_tangent = J_stored * PlusJacobian, so PlusJacobian here is the selection that
// reads those tangent columns back: stored columns 0-2 (rotation) and 4-6 (centre), column 3
// unused (0). This is a convention between this manifold and those costs: every cost on a pose
// block must follow it.
//
// The scale gauge (bundle_adjustment.hpp) fixes one centre coordinate of one pose. Its manifold
// keeps the 6 tangent values and ignores the fixed one (its Jacobian column is zero, so the step
// along it is zero), instead of a 5-value tangent: all pose blocks keep one size, which Ceres'
// fixed-size Schur specialisations need (with refined intrinsics the eliminator stays dynamic).
#pragma once

#include <ceres/manifold.h>

namespace sfm_pruning::bundle {

class PoseManifold final : public ceres::Manifold {
 public:
  // fixed_centre_axis: 0, 1 or 2 holds that centre coordinate; -1 holds none.
  explicit PoseManifold(int fixed_centre_axis = -1) : fixed_centre_axis_(fixed_centre_axis) {}

  int AmbientSize() const override { return 7; }
  int TangentSize() const override { return 6; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

 private:
  int fixed_centre_axis_;
};

}  // namespace sfm_pruning::bundle
