#include "sfm_pruning/geometry/fundamental_matrix.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

// Hartley's normalisation: centroid to the origin, mean distance sqrt(2).
Eigen::Matrix3d NormalizingTransform(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  double mean_distance = 0.0;
  for (const Eigen::Vector2d& p : points) mean_distance += (p - centroid).norm();
  mean_distance /= static_cast<double>(points.size());
  const double scale = mean_distance > 0.0 ? std::sqrt(2.0) / mean_distance : 1.0;
  Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
  T(0, 0) = T(1, 1) = scale;
  T(0, 2) = -scale * centroid.x();
  T(1, 2) = -scale * centroid.y();
  return T;
}

// Weighted linear fit in normalised coordinates, rank 2 enforced; false when degenerate.
bool WeightedLinearFit(const std::vector<Eigen::Vector3d>& n_i, const std::vector<Eigen::Vector3d>& n_j,
                       const std::vector<double>& weights, Eigen::Matrix3d* F_normalized, double* definition) {
  // Normal equations A^T W A (9x9): the null vector is its smallest eigenvector.
  Eigen::Matrix<double, 9, 9> normal = Eigen::Matrix<double, 9, 9>::Zero();
  for (size_t k = 0; k < n_i.size(); ++k) {
    Eigen::Matrix<double, 9, 1> row;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) row(3 * a + b) = n_j[k](a) * n_i[k](b);
    }
    normal.noalias() += weights[k] * row * row.transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix<double, 9, 9>> svd(normal, Eigen::ComputeFullV);
  const Eigen::Matrix<double, 9, 1> singular = svd.singularValues();
  // The second-smallest eigenvalue must stand clear of the smallest, else the fit is ambiguous.
  if (!(singular(7) > 1e-12 * singular(0))) return false;
  *definition = singular(8) > 0.0 ? std::sqrt(singular(7) / singular(8)) : std::numeric_limits<double>::infinity();
  const Eigen::Matrix<double, 9, 1> f = svd.matrixV().col(8);
  Eigen::Matrix3d F;
  F << f(0), f(1), f(2), f(3), f(4), f(5), f(6), f(7), f(8);
  Eigen::JacobiSVD<Eigen::Matrix3d> rank(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d values = rank.singularValues();
  values(2) = 0.0;
  *F_normalized = rank.matrixU() * values.asDiagonal() * rank.matrixV().transpose();
  return true;
}

}  // namespace

double SampsonDistance(const Eigen::Matrix3d& F, const Eigen::Vector2d& x_i, const Eigen::Vector2d& x_j) {
  const Eigen::Vector3d h_i = x_i.homogeneous();
  const Eigen::Vector3d h_j = x_j.homogeneous();
  const Eigen::Vector3d Fx_i = F * h_i;
  const Eigen::Vector3d Ftx_j = F.transpose() * h_j;
  const double denominator = Fx_i.head<2>().squaredNorm() + Ftx_j.head<2>().squaredNorm();
  if (!(denominator > 0.0)) return 0.0;
  return std::abs(h_j.dot(Fx_i)) / std::sqrt(denominator);
}

bool EstimateFundamentalMatrix(const std::vector<Eigen::Vector2d>& points_i, const std::vector<Eigen::Vector2d>& points_j,
                               const FundamentalMatrixOptions& options, Eigen::Matrix3d* F, double* definition) {
  options.Check();
  if (points_i.size() != points_j.size() || points_i.size() < 8) return false;
  const Eigen::Matrix3d T_i = NormalizingTransform(points_i);
  const Eigen::Matrix3d T_j = NormalizingTransform(points_j);
  std::vector<Eigen::Vector3d> n_i(points_i.size()), n_j(points_j.size());
  for (size_t k = 0; k < points_i.size(); ++k) {
    n_i[k] = T_i * points_i[k].homogeneous();
    n_j[k] = T_j * points_j[k].homogeneous();
  }
  std::vector<double> weights(points_i.size(), 1.0);
  Eigen::Matrix3d F_normalized;
  double fit_definition = 0.0;
  if (!WeightedLinearFit(n_i, n_j, weights, &F_normalized, &fit_definition)) return false;
  Eigen::Matrix3d estimate = T_j.transpose() * F_normalized * T_i;
  const double scale2 = options.robust_scale * options.robust_scale;
  for (int iteration = 0; iteration < options.num_reweighting_iterations; ++iteration) {
    for (size_t k = 0; k < points_i.size(); ++k) {
      // Dividing the algebraic residual's weight by the Sampson denominator makes the weighted
      // linear fit minimise the (robustified) Sampson distance itself.
      const Eigen::Vector3d Fx_i = estimate * points_i[k].homogeneous();
      const Eigen::Vector3d Ftx_j = estimate.transpose() * points_j[k].homogeneous();
      const double denominator = Fx_i.head<2>().squaredNorm() + Ftx_j.head<2>().squaredNorm();
      const double d = SampsonDistance(estimate, points_i[k], points_j[k]);
      weights[k] = denominator > 0.0 ? 1.0 / ((1.0 + d * d / scale2) * denominator) : 0.0;
    }
    if (!WeightedLinearFit(n_i, n_j, weights, &F_normalized, &fit_definition)) break;
    estimate = T_j.transpose() * F_normalized * T_i;
  }
  *F = estimate / estimate.norm();
  if (definition != nullptr) *definition = fit_definition;
  return true;
}

void FundamentalMatrixOptions::Check() const {
  // The Cauchy weight divides by robust_scale^2; an infinite scale is the plain Sampson fit.
  RequirePositiveAtMost(robust_scale, std::numeric_limits<double>::infinity(), "FundamentalMatrixOptions::robust_scale");
  RequireAtLeast(num_reweighting_iterations, 0, "FundamentalMatrixOptions::num_reweighting_iterations");
}

}  // namespace sfm_pruning
