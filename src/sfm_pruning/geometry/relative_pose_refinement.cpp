#include "sfm_pruning/geometry/relative_pose_refinement.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <ceres/jet.h>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

// The five local coordinates of the pose: a rotation increment (R <- Exp(omega) R) and a step of
// the translation in the plane orthogonal to it (t <- normalise(t + B xi)).
constexpr int kNumParameters = 5;
using Jet = ceres::Jet<double, kNumParameters>;
using Vector5d = Eigen::Matrix<double, kNumParameters, 1>;
using Matrix5d = Eigen::Matrix<double, kNumParameters, kNumParameters>;

// Angular epipolar error of one correspondence (epipolar_geometry.hpp's AngularEpipolarError)
// given the rotated bearing R b_i; the epsilon keeps the square root differentiable for a
// correspondence at the epipoles.
template <typename T>
T AngularEpipolarResidual(const Eigen::Matrix<T, 3, 1>& rotated_bearing_i, const Eigen::Matrix<T, 3, 1>& translation,
                          const Eigen::Matrix<T, 3, 1>& bearing_j) {
  const Eigen::Matrix<T, 3, 1> E_bi = translation.cross(rotated_bearing_i);
  const T denominator = sqrt(E_bi.squaredNorm() + bearing_j.cross(translation).squaredNorm() + T(1e-20));
  return bearing_j.dot(E_bi) / denominator;
}

// Two unit vectors orthogonal to `t` and to each other.
Eigen::Matrix<double, 3, 2> TangentBasis(const Eigen::Vector3d& t) {
  const Eigen::Vector3d helper = std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = t.cross(helper).normalized();
  basis.col(1) = t.cross(basis.col(0));
  return basis;
}

class EpipolarProblem {
 public:
  EpipolarProblem(const std::vector<Eigen::Vector3d>& bearings_i, const std::vector<Eigen::Vector3d>& bearings_j,
                  const std::vector<int>& indices, double loss_scale_rad)
      : loss_scale_sq_(loss_scale_rad > 0.0 ? loss_scale_rad * loss_scale_rad : 0.0) {
    bearings_i_.reserve(indices.size());
    bearings_j_.reserve(indices.size());
    for (const int k : indices) {
      bearings_i_.push_back(bearings_i[k].normalized());
      bearings_j_.push_back(bearings_j[k].normalized());
    }
  }

  // Ceres' convention: 1/2 sum of rho(r^2), rho the identity or the Cauchy loss.
  double Cost(const RelativePose& pose) const {
    double cost = 0.0;
    for (size_t k = 0; k < bearings_i_.size(); ++k) {
      const double r = AngularEpipolarResidual<double>(pose.rotation * bearings_i_[k], pose.translation, bearings_j_[k]);
      cost += Rho(r * r);
    }
    return 0.5 * cost;
  }

  // Gauss-Newton normal equations at `pose` in the local coordinates, each residual weighted by
  // the loss's derivative (iteratively reweighted least squares: the same minimum as the loss),
  // or unweighted (the pose's covariance); the sum of squared residuals when asked for.
  void NormalEquations(const RelativePose& pose, const Eigen::Matrix<double, 3, 2>& basis, Matrix5d* hessian,
                       Vector5d* gradient, bool weighted = true, double* squared_residuals = nullptr) const {
    hessian->setZero();
    gradient->setZero();
    if (squared_residuals != nullptr) *squared_residuals = 0.0;
    Eigen::Matrix<Jet, 3, 1> translation;
    for (int d = 0; d < 3; ++d) {
      translation[d] = Jet(pose.translation[d]);
      translation[d].v[3] = basis(d, 0);
      translation[d].v[4] = basis(d, 1);
    }
    for (size_t k = 0; k < bearings_i_.size(); ++k) {
      // d(Exp(omega) a)/d omega at omega = 0 is -[a]_x: a + omega x a to first order.
      const Eigen::Vector3d a = pose.rotation * bearings_i_[k];
      Eigen::Matrix<Jet, 3, 1> rotated;
      for (int d = 0; d < 3; ++d) rotated[d] = Jet(a[d]);
      for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d derivative = Eigen::Vector3d::Unit(axis).cross(a);
        for (int d = 0; d < 3; ++d) rotated[d].v[axis] = derivative[d];
      }
      const Jet r = AngularEpipolarResidual<Jet>(rotated, translation, bearings_j_[k].cast<Jet>());
      const double weight = weighted ? Weight(r.a * r.a) : 1.0;
      if (squared_residuals != nullptr) *squared_residuals += r.a * r.a;
      const Vector5d jacobian = r.v;
      hessian->noalias() += weight * jacobian * jacobian.transpose();
      gradient->noalias() += weight * r.a * jacobian;
    }
  }

 private:
  double Rho(double squared) const {
    return loss_scale_sq_ > 0.0 ? loss_scale_sq_ * std::log1p(squared / loss_scale_sq_) : squared;
  }
  double Weight(double squared) const { return loss_scale_sq_ > 0.0 ? 1.0 / (1.0 + squared / loss_scale_sq_) : 1.0; }

 public:
  size_t size() const { return bearings_i_.size(); }

 private:

  double loss_scale_sq_;
  std::vector<Eigen::Vector3d> bearings_i_;
  std::vector<Eigen::Vector3d> bearings_j_;
};

// First-order covariance of the rotation increment at `pose`: sigma^2 (J^T J)^-1, sigma^2 the
// residuals' variance with five degrees of freedom taken, J unweighted, the translation's two
// coordinates marginalised (the rotation block of the full inverse). Infinite when J^T J is
// singular to working precision (a degenerate configuration: too few correspondences or a
// structure that does not fix the pose).
Eigen::Matrix3d RotationCovariance(const EpipolarProblem& problem, const RelativePose& pose) {
  const Eigen::Matrix<double, 3, 2> basis = TangentBasis(pose.translation);
  Matrix5d normal;
  Vector5d gradient;
  double squared_residuals = 0.0;
  problem.NormalEquations(pose, basis, &normal, &gradient, /*weighted=*/false, &squared_residuals);
  const Eigen::SelfAdjointEigenSolver<Matrix5d> eigen(normal);
  const double largest = eigen.eigenvalues().maxCoeff();
  if (eigen.info() != Eigen::Success || !(eigen.eigenvalues().minCoeff() > 1e-12 * largest)) {
    return Eigen::Matrix3d::Constant(std::numeric_limits<double>::infinity());
  }
  const double variance = squared_residuals / static_cast<double>(problem.size() - kNumParameters);
  const Matrix5d inverse = eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().asDiagonal() *
                           eigen.eigenvectors().transpose();
  return variance * inverse.topLeftCorner<3, 3>();
}

RelativePose Step(const RelativePose& pose, const Eigen::Matrix<double, 3, 2>& basis, const Vector5d& step) {
  RelativePose moved;
  moved.rotation = ProjectToRotation(ExpSO3(step.head<3>()) * pose.rotation);
  moved.translation = (pose.translation + basis * step.tail<2>()).normalized();
  return moved;
}

}  // namespace

RelativePoseRefinementSummary RefineRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                                 const std::vector<Eigen::Vector3d>& bearings_j,
                                                 const std::vector<int>& indices,
                                                 const RelativePoseRefinementOptions& options,
                                                 RelativePose* relative_ij) {
  options.Check();
  RelativePoseRefinementSummary summary;
  if (indices.size() < 5) return summary;

  const EpipolarProblem problem(bearings_i, bearings_j, indices, options.loss_scale_rad);
  RelativePose pose = *relative_ij;
  pose.translation.normalize();
  double cost = problem.Cost(pose);
  summary.initial_cost = cost;
  if (!std::isfinite(cost)) return summary;

  // Levenberg-Marquardt on the five local coordinates. Noise-free data must converge to machine
  // precision, hence the tolerances far below what a photogrammetric residual needs.
  constexpr double kRelativeDecreaseTolerance = 1e-15;
  constexpr double kGradientTolerance = 1e-15;
  constexpr double kStepTolerance = 1e-12;
  double damping = 1e-4;
  for (int iteration = 0; iteration < options.max_num_iterations; ++iteration) {
    const Eigen::Matrix<double, 3, 2> basis = TangentBasis(pose.translation);
    Matrix5d hessian;
    Vector5d gradient;
    problem.NormalEquations(pose, basis, &hessian, &gradient);
    if (gradient.lpNorm<Eigen::Infinity>() <= kGradientTolerance) break;
    bool improved = false;
    bool step_too_small = false;
    while (damping < 1e16) {
      Matrix5d damped = hessian;
      damped.diagonal() += damping * hessian.diagonal().cwiseMax(1e-12);
      const Vector5d step = damped.ldlt().solve(-gradient);
      if (!step.allFinite()) break;
      step_too_small = step.norm() <= kStepTolerance;
      const RelativePose candidate = Step(pose, basis, step);
      const double candidate_cost = problem.Cost(candidate);
      if (std::isfinite(candidate_cost) && candidate_cost < cost) {
        const double decrease = cost - candidate_cost;
        pose = candidate;
        cost = candidate_cost;
        damping = std::max(damping / 10.0, 1e-12);
        improved = decrease > kRelativeDecreaseTolerance * cost;
        break;
      }
      if (step_too_small) break;
      damping *= 10.0;
    }
    if (!improved || step_too_small) break;
  }

  summary.final_cost = cost;
  summary.converged = pose.rotation.allFinite() && pose.translation.allFinite();
  if (!summary.converged) return summary;
  if (indices.size() > static_cast<size_t>(kNumParameters)) summary.rotation_covariance = RotationCovariance(problem, pose);
  relative_ij->rotation = pose.rotation;
  relative_ij->translation = pose.translation;
  return summary;
}

double RelativePoseRefinementSummary::RotationStdRad() const {
  if (!rotation_covariance.allFinite()) return std::numeric_limits<double>::infinity();
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(rotation_covariance).eigenvalues().maxCoeff();
  return std::sqrt(std::max(largest, 0.0));
}

void RelativePoseRefinementOptions::Check() const {
  // <= 0 is plain least squares; a Cauchy scale must be finite (an infinite one makes the cost NaN).
  if (!(loss_scale_rad <= 0.0)) {
    RequirePositiveAtMost(loss_scale_rad, std::numeric_limits<double>::max(),
                          "RelativePoseRefinementOptions::loss_scale_rad (or <= 0: plain least squares)");
  }
  // 0 only evaluates the initial cost.
  RequireAtLeast(max_num_iterations, 0, "RelativePoseRefinementOptions::max_num_iterations");
}

}  // namespace sfm_pruning
