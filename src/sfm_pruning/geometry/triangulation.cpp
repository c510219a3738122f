#include "sfm_pruning/geometry/triangulation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace sfm_pruning {
namespace {

// Two unit vectors spanning the plane orthogonal to `v`.
void OrthonormalComplement(const Eigen::Vector3d& v, Eigen::Vector3d* u, Eigen::Vector3d* w) {
  const Eigen::Vector3d n = v.normalized();
  *u = n.unitOrthogonal();
  *w = n.cross(*u);
}

std::optional<Eigen::Vector3d> TriangulateDlt(const std::vector<Pose>& poses,
                                              const std::vector<Eigen::Vector3d>& bearings) {
  // The camera-frame point P X (P = [R | t]) is parallel to the bearing b, so it has no component
  // along the two directions orthogonal to b: two linear equations per view in homogeneous X.
  Eigen::MatrixXd A(2 * poses.size(), 4);
  for (size_t k = 0; k < poses.size(); ++k) {
    Eigen::Matrix<double, 3, 4> P;
    P << poses[k].rotation, poses[k].translation();
    Eigen::Vector3d u, w;
    OrthonormalComplement(bearings[k], &u, &w);
    A.row(2 * k) = u.transpose() * P;
    A.row(2 * k + 1) = w.transpose() * P;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  // A rank below 3 means the rays do not pin the point down (parallel rays, one distinct view).
  const Eigen::VectorXd& s = svd.singularValues();
  if (s(2) <= 1e-12 * s(0)) return std::nullopt;
  const Eigen::Vector4d X = svd.matrixV().col(3);
  if (std::abs(X(3)) <= 1e-12 * X.head<3>().norm()) return std::nullopt;  // at infinity
  return Eigen::Vector3d(X.head<3>() / X(3));
}

std::optional<Eigen::Vector3d> TriangulateMidpoint(const std::vector<Pose>& poses,
                                                   const std::vector<Eigen::Vector3d>& bearings) {
  // Minimises sum_k |(I - d_k d_k^T)(X - c_k)|^2 with d_k the unit world ray of view k.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Vector3d d = (poses[k].rotation.transpose() * bearings[k]).normalized();
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += projector;
    b += projector * poses[k].center;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(A);
  // The smallest eigenvalue is ~ n sin^2(parallax): zero for parallel rays.
  if (eigen.eigenvalues()(0) <= 1e-12 * eigen.eigenvalues()(2)) return std::nullopt;
  return Eigen::Vector3d(A.ldlt().solve(b));
}

}  // namespace

std::optional<TwoViewPoint> TriangulateTwoView(const RelativePose& relative_ij, const Eigen::Vector3d& bearing_i,
                                               const Eigen::Vector3d& bearing_j, double min_parallax_rad) {
  // In camera i's frame: ray i is a * b_i, ray j is c + s * d with c the centre of j and d the
  // bearing of j rotated into frame i. Least squares on [b_i, -d] (a, s) = c.
  const Eigen::Vector3d c = relative_ij.CenterOfJInI();
  const Eigen::Vector3d d = relative_ij.rotation.transpose() * bearing_j;
  if (AngleBetweenVectors(bearing_i, d) < min_parallax_rad) return std::nullopt;
  Eigen::Matrix<double, 3, 2> A;
  A << bearing_i, -d;
  const Eigen::Vector2d depths = (A.transpose() * A).ldlt().solve(A.transpose() * c);
  TwoViewPoint result;
  result.depth_i = depths(0);
  result.depth_j = depths(1);
  result.point_i = 0.5 * (depths(0) * bearing_i + c + depths(1) * d);
  return result;
}

std::optional<Eigen::Vector3d> TriangulateMultiView(const std::vector<Pose>& poses,
                                                    const std::vector<Eigen::Vector3d>& bearings,
                                                    TriangulationMethod method) {
  if (poses.size() < 2 || poses.size() != bearings.size()) return std::nullopt;
  return method == TriangulationMethod::kDlt ? TriangulateDlt(poses, bearings)
                                             : TriangulateMidpoint(poses, bearings);
}

double TriangulationAngle(const Eigen::Vector3d& center_a, const Eigen::Vector3d& center_b,
                          const Eigen::Vector3d& point) {
  return AngleBetweenVectors(point - center_a, point - center_b);
}

double MaxTriangulationAngle(const std::vector<Eigen::Vector3d>& centers, const Eigen::Vector3d& point) {
  double max_angle = 0.0;
  for (size_t a = 0; a < centers.size(); ++a) {
    for (size_t b = a + 1; b < centers.size(); ++b) {
      max_angle = std::max(max_angle, TriangulationAngle(centers[a], centers[b], point));
    }
  }
  return max_angle;
}

bool IsInFrontOfAll(const std::vector<Pose>& poses, const std::vector<Eigen::Vector3d>& bearings,
                    const Eigen::Vector3d& point_world) {
  for (size_t k = 0; k < poses.size(); ++k) {
    if (!IsInFront(poses[k], bearings[k], point_world)) return false;
  }
  return true;
}

}  // namespace sfm_pruning
