#include "sfm_pruning/eval/similarity_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

constexpr size_t kMinimalSample = 3;
// Ratio of the second to the first eigenvalue of the scatter matrix below which points are
// treated as collinear (eigenvalues are squared lengths: 1e-10 means 1e-5 in length).
constexpr double kCollinearEigenvalueRatio = 1e-10;
constexpr int kMaxRefinements = 20;

bool IsDegenerate(const Eigen::Matrix3Xd& points) {
  if (points.cols() < static_cast<Eigen::Index>(kMinimalSample)) return true;
  const Eigen::Matrix3Xd centered = points.colwise() - points.rowwise().mean();
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centered * centered.transpose(), Eigen::EigenvaluesOnly)
          .eigenvalues();  // ascending
  return !(eigenvalues(1) > kCollinearEigenvalueRatio * eigenvalues(2));
}

Eigen::Matrix3Xd ToMatrix(const std::vector<Eigen::Vector3d>& points, const std::vector<size_t>& indices) {
  Eigen::Matrix3Xd matrix(3, indices.size());
  for (size_t k = 0; k < indices.size(); ++k) matrix.col(static_cast<Eigen::Index>(k)) = points[indices[k]];
  return matrix;
}

std::optional<Similarity3> FitOnSubset(const std::vector<Eigen::Vector3d>& source,
                                       const std::vector<Eigen::Vector3d>& target, const std::vector<size_t>& indices) {
  const Eigen::Matrix3Xd src = ToMatrix(source, indices);
  const Eigen::Matrix3Xd dst = ToMatrix(target, indices);
  if (IsDegenerate(src) || IsDegenerate(dst)) return std::nullopt;
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, /*with_scaling=*/true);
  Similarity3 similarity;
  similarity.scale = T.block<3, 1>(0, 0).norm();
  if (!(similarity.scale > 0.0) || !std::isfinite(similarity.scale)) return std::nullopt;
  similarity.rotation = T.block<3, 3>(0, 0) / similarity.scale;
  similarity.translation = T.block<3, 1>(0, 3);
  return similarity;
}

double SceneRadius(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  std::vector<double> distances;
  distances.reserve(points.size());
  for (const Eigen::Vector3d& p : points) distances.push_back((p - centroid).norm());
  return Median(std::move(distances));
}

std::vector<size_t> InlierIndices(const Similarity3& transform, const std::vector<Eigen::Vector3d>& source,
                                  const std::vector<Eigen::Vector3d>& target, double threshold) {
  std::vector<size_t> inliers;
  for (size_t k = 0; k < source.size(); ++k) {
    if ((target[k] - transform.Apply(source[k])).norm() < threshold) inliers.push_back(k);
  }
  return inliers;
}

// MSAC score: squared residuals truncated at the threshold; lower is better.
double TruncatedCost(const Similarity3& transform, const std::vector<Eigen::Vector3d>& source,
                     const std::vector<Eigen::Vector3d>& target, double threshold) {
  double cost = 0.0;
  for (size_t k = 0; k < source.size(); ++k) {
    cost += std::min((target[k] - transform.Apply(source[k])).squaredNorm(), threshold * threshold);
  }
  return cost;
}

std::vector<size_t> SampleDistinct(size_t count, size_t population, std::mt19937_64& rng) {
  std::uniform_int_distribution<size_t> pick(0, population - 1);
  std::vector<size_t> sample;
  while (sample.size() < count) {
    const size_t index = pick(rng);
    if (std::find(sample.begin(), sample.end(), index) == sample.end()) sample.push_back(index);
  }
  return sample;
}

}  // namespace

std::optional<Similarity3> FitSimilarityLeastSquares(const std::vector<Eigen::Vector3d>& source,
                                                     const std::vector<Eigen::Vector3d>& target) {
  if (source.size() != target.size()) return std::nullopt;
  std::vector<size_t> all(source.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = k;
  return FitOnSubset(source, target, all);
}

std::optional<RobustSimilarity> FitSimilarityRobust(const std::vector<Eigen::Vector3d>& source,
                                                    const std::vector<Eigen::Vector3d>& target,
                                                    const RobustSimilarityOptions& options) {
  options.Check();
  if (source.size() != target.size() || source.size() < kMinimalSample) return std::nullopt;
  const double threshold = options.inlier_threshold_scene_fraction * SceneRadius(target);
  if (!(threshold > 0.0)) return std::nullopt;

  std::mt19937_64 rng(options.seed);
  std::optional<Similarity3> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const std::optional<Similarity3> candidate =
        FitOnSubset(source, target, SampleDistinct(kMinimalSample, source.size(), rng));
    if (!candidate) continue;
    const double cost = TruncatedCost(*candidate, source, target, threshold);
    if (cost < best_cost) {
      best_cost = cost;
      best = candidate;
    }
  }
  if (!best) return std::nullopt;

  // Refit on the inliers until the set is stable; the least-squares fit is the reported one.
  std::vector<size_t> inliers = InlierIndices(*best, source, target, threshold);
  for (int refinement = 0; refinement < kMaxRefinements; ++refinement) {
    const std::optional<Similarity3> refit = FitOnSubset(source, target, inliers);
    if (!refit) break;
    best = refit;
    std::vector<size_t> updated = InlierIndices(*best, source, target, threshold);
    if (updated == inliers) break;
    inliers = std::move(updated);
  }
  if (inliers.size() < kMinimalSample) return std::nullopt;

  RobustSimilarity result;
  result.transform = *best;
  result.inliers.assign(source.size(), false);
  for (size_t k : inliers) result.inliers[k] = true;
  result.num_inliers = inliers.size();
  result.inlier_threshold = threshold;
  return result;
}

void RobustSimilarityOptions::Check() const {
  // A threshold of 0 admits no inlier; an infinite one makes every point one.
  RequirePositiveFinite(inlier_threshold_scene_fraction, "RobustSimilarityOptions::inlier_threshold_scene_fraction");
  // Without a sample there is no fit.
  RequireAtLeast(max_iterations, 1, "RobustSimilarityOptions::max_iterations");
}

}  // namespace sfm_pruning
