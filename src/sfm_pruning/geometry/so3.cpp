#include "sfm_pruning/geometry/so3.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

double WeightAt(const std::vector<double>& weights, size_t k) { return weights.empty() ? 1.0 : weights[k]; }

}  // namespace

Eigen::Matrix3d SkewMatrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return m;
}

Eigen::Vector3d LogSO3(const Eigen::Matrix3d& rotation) {
  // R = I + sin(a) [n]_x + (1 - cos(a)) [n]_x^2, so the antisymmetric part gives sin(a) n and the
  // trace gives cos(a); atan2 of the two is accurate over the whole range [0, pi].
  const Eigen::Vector3d sin_axis = 0.5 * Eigen::Vector3d(rotation(2, 1) - rotation(1, 2),
                                                         rotation(0, 2) - rotation(2, 0),
                                                         rotation(1, 0) - rotation(0, 1));
  const double cos_angle = std::clamp(0.5 * (rotation.trace() - 1.0), -1.0, 1.0);
  const double sin_angle = sin_axis.norm();
  const double angle = std::atan2(sin_angle, cos_angle);

  if (cos_angle >= 0.0) {
    // Angle below 90 degrees: angle / sin(angle) is in [1, pi/2] and tends to 1 at zero.
    if (sin_angle < 1e-300) return sin_axis;
    return sin_axis * (angle / sin_angle);
  }
  // Angle above 90 degrees: sin(a) n loses precision as a -> pi. The symmetric part
  // (R + R^T)/2 = cos(a) I + (1 - cos(a)) n n^T gives n n^T with 1 - cos(a) >= 1 in the divisor.
  const Eigen::Matrix3d n_nt =
      (0.5 * (rotation + rotation.transpose()) - cos_angle * Eigen::Matrix3d::Identity()) / (1.0 - cos_angle);
  int column = 0;
  n_nt.diagonal().maxCoeff(&column);
  Eigen::Vector3d axis = n_nt.col(column).normalized();  // n * n_c, so n up to sign
  if (axis.dot(sin_axis) < 0.0) axis = -axis;            // the sign of sin(a) n decides
  return angle * axis;
}

Eigen::Matrix3d ExpSO3(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-8) {
    // Second-order Taylor expansion; the next terms are below 1e-24.
    const Eigen::Matrix3d K = SkewMatrix(omega);
    return Eigen::Matrix3d::Identity() + K + 0.5 * K * K;
  }
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

Eigen::Matrix3d ProjectToRotation(const Eigen::Matrix3d& matrix) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(matrix, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0.0) U.col(2) *= -1.0;
  return U * svd.matrixV().transpose();
}

Eigen::Matrix3d ChordalMeanRotation(const std::vector<Eigen::Matrix3d>& rotations,
                                    const std::vector<double>& weights) {
  if (rotations.empty()) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (size_t k = 0; k < rotations.size(); ++k) sum += WeightAt(weights, k) * rotations[k];
  return ProjectToRotation(sum);
}

RotationMeanResult GeodesicMeanRotation(const std::vector<Eigen::Matrix3d>& rotations,
                                        const GeodesicMeanOptions& options,
                                        const std::vector<double>& weights) {
  options.Check();
  RotationMeanResult result;
  if (rotations.empty()) return result;
  result.rotation = ChordalMeanRotation(rotations, weights);
  const bool l1 = options.norm == GeodesicMeanOptions::Norm::kL1;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // Tangent-space residuals at the current estimate; L2 averages them (Karcher), L1 weights
    // each by the inverse of its length (one Weiszfeld step).
    Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
    double weight_sum = 0.0;
    for (size_t k = 0; k < rotations.size(); ++k) {
      const Eigen::Vector3d residual = LogSO3(result.rotation.transpose() * rotations[k]);
      double w = WeightAt(weights, k);
      if (l1) w /= std::max(residual.norm(), options.l1_min_residual_rad);
      weighted_sum += w * residual;
      weight_sum += w;
    }
    if (weight_sum <= 0.0) break;
    const Eigen::Vector3d step = weighted_sum / weight_sum;
    result.rotation = ProjectToRotation(result.rotation * ExpSO3(step));
    result.num_iterations = iteration + 1;
    if (step.norm() < options.convergence_tolerance_rad) {
      result.converged = true;
      break;
    }
  }
  return result;
}

void GeodesicMeanOptions::Check() const {
  // 0 iterations returns the chordal mean; a tolerance of 0 runs every iteration.
  RequireAtLeast(max_iterations, 0, "GeodesicMeanOptions::max_iterations");
  RequireAtLeast(convergence_tolerance_rad, 0.0, "GeodesicMeanOptions::convergence_tolerance_rad");
  // 0 would divide by zero; residuals are angles in [0, pi], so a floor above pi clamps them all.
  RequirePositiveAtMost(l1_min_residual_rad, M_PI, "GeodesicMeanOptions::l1_min_residual_rad");
}

}  // namespace sfm_pruning
