#include "sfm_pruning/geometry/relative_pose_refinement.hpp"

#include <limits>
#include <memory>

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

// Angular epipolar error of one correspondence, as epipolar_geometry.hpp's AngularEpipolarError
// but differentiable: parameters are the rotation update delta and the unit translation.
struct AngularEpipolarCost {
  AngularEpipolarCost(const Eigen::Vector3d& rotated_bearing_i, const Eigen::Vector3d& bearing_j)
      : rotated_bearing_i_(rotated_bearing_i), bearing_j_(bearing_j) {}

  template <typename T>
  bool operator()(const T* delta, const T* translation, T* residual) const {
    using Vector3T = Eigen::Matrix<T, 3, 1>;
    const Vector3T r0_bi = rotated_bearing_i_.cast<T>();
    Vector3T r_bi;
    ceres::AngleAxisRotatePoint(delta, r0_bi.data(), r_bi.data());
    const Eigen::Map<const Vector3T> t(translation);
    const Vector3T b_j = bearing_j_.cast<T>();
    const Vector3T E_bi = t.cross(r_bi);
    // The epsilon keeps the square root differentiable for a correspondence at the epipoles.
    const T denominator = ceres::sqrt(E_bi.squaredNorm() + b_j.cross(t).squaredNorm() + T(1e-20));
    residual[0] = b_j.dot(E_bi) / denominator;
    return true;
  }

  Eigen::Vector3d rotated_bearing_i_;  // R_0 b_i
  Eigen::Vector3d bearing_j_;
};

}  // namespace

RelativePoseRefinementSummary RefineRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                                 const std::vector<Eigen::Vector3d>& bearings_j,
                                                 const std::vector<int>& indices,
                                                 const RelativePoseRefinementOptions& options,
                                                 RelativePose* relative_ij) {
  options.Check();
  RelativePoseRefinementSummary summary;
  if (indices.size() < 5) return summary;

  const Eigen::Matrix3d R0 = relative_ij->rotation;
  double delta[3] = {0.0, 0.0, 0.0};
  Eigen::Vector3d translation = relative_ij->translation.normalized();

  ceres::Problem problem;
  for (const int k : indices) {
    auto* cost = new ceres::AutoDiffCostFunction<AngularEpipolarCost, 1, 3, 3>(
        new AngularEpipolarCost(R0 * bearings_i[k].normalized(), bearings_j[k].normalized()));
    ceres::LossFunction* loss = options.loss_scale_rad > 0.0 ? new ceres::CauchyLoss(options.loss_scale_rad) : nullptr;
    problem.AddResidualBlock(cost, loss, delta, translation.data());
  }
  problem.SetManifold(translation.data(), new ceres::SphereManifold<3>());

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options.max_num_iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  // Noise-free data must converge to machine precision, not to Ceres' default 1e-6 relative cost.
  solver_options.function_tolerance = 1e-15;
  solver_options.gradient_tolerance = 1e-15;
  solver_options.parameter_tolerance = 1e-12;
  ceres::Solver::Summary ceres_summary;
  ceres::Solve(solver_options, &problem, &ceres_summary);

  summary.initial_cost = ceres_summary.initial_cost;
  summary.final_cost = ceres_summary.final_cost;
  summary.converged = ceres_summary.IsSolutionUsable();
  if (!summary.converged) return summary;
  relative_ij->rotation = ProjectToRotation(ExpSO3(Eigen::Vector3d(delta[0], delta[1], delta[2])) * R0);
  relative_ij->translation = translation.normalized();
  return summary;
}

void RelativePoseRefinementOptions::Check() const {
  // <= 0 is plain least squares; a Cauchy scale must be finite (an infinite one makes the cost NaN).
  if (!(loss_scale_rad <= 0.0)) {
    RequirePositiveAtMost(loss_scale_rad, std::numeric_limits<double>::max(),
                          "RelativePoseRefinementOptions::loss_scale_rad (or <= 0: plain least squares)");
  }
  // 0 only evaluates the initial cost (Ceres accepts it).
  RequireAtLeast(max_num_iterations, 0, "RelativePoseRefinementOptions::max_num_iterations");
}

}  // namespace sfm_pruning
