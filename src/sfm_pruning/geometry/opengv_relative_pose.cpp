#include "sfm_pruning/geometry/opengv_relative_pose.hpp"

// OpenGV's sac headers use INT_MAX, pow and std::numeric_limits without including them.
#include <climits>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <opengv/relative_pose/CentralRelativeAdapter.hpp>
#include <opengv/sac_problems/relative_pose/CentralRelativePoseSacProblem.hpp>
#include <opengv/sac/Ransac.hpp>

#include "sfm_pruning/geometry/epipolar_geometry.hpp"
#include "sfm_pruning/geometry/opengv_boundary.hpp"
#include "sfm_pruning/geometry/relative_pose_refinement.hpp"
#include "sfm_pruning/geometry/triangulation.hpp"

namespace sfm_pruning {
namespace {

using SacProblem = opengv::sac_problems::relative_pose::CentralRelativePoseSacProblem;

struct InlierSet {
  std::vector<int> inliers;
  int num_in_front = 0;
};

// Inliers of `pose`: angular epipolar error within the threshold and, when asked, not
// triangulated behind a camera. Rays with less parallax than the threshold cannot tell front
// from back, so they are never rejected for cheirality.
InlierSet SelectInliers(const RelativePose& pose, const std::vector<Eigen::Vector3d>& bearings_i,
                        const std::vector<Eigen::Vector3d>& bearings_j, double max_error_rad,
                        bool reject_points_behind) {
  InlierSet set;
  for (size_t k = 0; k < bearings_i.size(); ++k) {
    if (AngularEpipolarError(pose, bearings_i[k], bearings_j[k]) > max_error_rad) continue;
    const std::optional<TwoViewPoint> point = TriangulateTwoView(pose, bearings_i[k], bearings_j[k], max_error_rad);
    const bool in_front = point && point->depth_i > 0.0 && point->depth_j > 0.0;
    if (in_front) ++set.num_in_front;
    if (!in_front && point && reject_points_behind) continue;
    set.inliers.push_back(static_cast<int>(k));
  }
  return set;
}

// OpenGV picks one of the four poses sharing the essential matrix from 3 extra sample points;
// with noise that pick can be wrong. All four have the same epipolar errors, so choose the one
// that puts the most epipolar inliers in front of both cameras.
RelativePose ResolveByCheirality(const RelativePose& pose, const std::vector<Eigen::Vector3d>& bearings_i,
                                 const std::vector<Eigen::Vector3d>& bearings_j, double max_error_rad) {
  RelativePose best = pose;
  int best_in_front = -1;
  for (const RelativePose& candidate : EssentialPoseCandidates(pose)) {
    const int in_front = SelectInliers(candidate, bearings_i, bearings_j, max_error_rad, false).num_in_front;
    if (in_front > best_in_front) {
      best_in_front = in_front;
      best = candidate;
    }
  }
  return best;
}

RelativePoseResult Failure(const std::string& reason) {
  RelativePoseResult result;
  result.reason = reason;
  return result;
}

}  // namespace

RelativePoseResult EstimateRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                        const std::vector<Eigen::Vector3d>& bearings_j,
                                        const RelativePoseOptions& options) {
  if (bearings_i.size() != bearings_j.size()) return Failure("bearing arrays differ in size");
  const opengv::bearingVectors_t opengv_i = ToOpenGVVectors(bearings_i);
  const opengv::bearingVectors_t opengv_j = ToOpenGVVectors(bearings_j);
  // View i is OpenGV's viewpoint 1 (see opengv_boundary.hpp). The adapter keeps references.
  opengv::relative_pose::CentralRelativeAdapter adapter(opengv_i, opengv_j);
  const auto algorithm = options.solver == RelativePoseOptions::Solver::kNister ? SacProblem::NISTER
                                                                                : SacProblem::STEWENIUS;
  // make_shared, never new: see docs/dependencies.md §0 (aligned operator delete in libopengv).
  const auto problem = std::make_shared<SacProblem>(adapter, algorithm, /*randomSeed=*/false);
  // Checked here because OpenGV prints to stderr instead of failing when the sample is too big.
  if (bearings_i.size() < static_cast<size_t>(problem->getSampleSize())) {
    return Failure("too few correspondences: " + std::to_string(bearings_i.size()) + " < " +
                   std::to_string(problem->getSampleSize()));
  }
  SeedOpenGVSampler(options.seed, problem.get());

  const double max_error_rad = DegToRad(options.max_angular_error_deg);
  opengv::sac::Ransac<SacProblem> ransac;
  ransac.sac_model_ = problem;
  ransac.threshold_ = OpenGVThresholdFromAngle(max_error_rad);
  ransac.max_iterations_ = options.max_iterations;
  ransac.probability_ = options.confidence;
  if (!ransac.computeModel(/*debug_verbosity_level=*/0)) return Failure("RANSAC found no model");

  RelativePose pose = RelativePoseFromOpenGV(ransac.model_coefficients_);
  if (!(pose.translation.norm() > 0.0) || !pose.rotation.allFinite()) return Failure("RANSAC model is degenerate");
  pose.translation.normalize();
  pose = ResolveByCheirality(pose, bearings_i, bearings_j, max_error_rad);

  InlierSet set = SelectInliers(pose, bearings_i, bearings_j, max_error_rad, options.reject_points_behind);
  RelativePoseRefinementOptions refinement;
  for (int round = 0; round < options.refinement_rounds; ++round) {
    RelativePose refined = pose;
    if (!RefineRelativePose(bearings_i, bearings_j, set.inliers, refinement, &refined).converged) break;
    InlierSet refined_set =
        SelectInliers(refined, bearings_i, bearings_j, max_error_rad, options.reject_points_behind);
    // Keep the refinement only when it does not lose support (a few borderline matches may move
    // across the threshold; losing many means the optimum drifted to a worse model).
    if (refined_set.inliers.size() < set.inliers.size() * 95 / 100) break;
    pose = refined;
    set = std::move(refined_set);
  }

  RelativePoseResult result;
  result.relative_pose = pose;
  result.num_ransac_iterations = ransac.iterations_;
  result.num_inliers = static_cast<int>(set.inliers.size());
  result.num_inliers_in_front = set.num_in_front;
  result.inliers = std::move(set.inliers);
  if (result.num_inliers < 5) {
    result.reason = "too few inliers after refinement: " + std::to_string(result.num_inliers);
    return result;
  }
  result.success = true;
  return result;
}

}  // namespace sfm_pruning
