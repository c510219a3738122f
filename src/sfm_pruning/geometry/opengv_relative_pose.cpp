#include "sfm_pruning/geometry/opengv_relative_pose.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <opengv/relative_pose/CentralRelativeAdapter.hpp>
#include <opengv/relative_pose/methods.hpp>
#include <opengv/sac_problems/relative_pose/CentralRelativePoseSacProblem.hpp>

#include "sfm_pruning/geometry/epipolar_geometry.hpp"
#include "sfm_pruning/geometry/opengv_boundary.hpp"
#include "sfm_pruning/geometry/opengv_ransac.hpp"
#include "sfm_pruning/geometry/relative_pose_refinement.hpp"
#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

using SacProblem = opengv::sac_problems::relative_pose::CentralRelativePoseSacProblem;

// OpenGV's CentralRelativePoseSacProblem draws 8 correspondences per hypothesis (5 for the
// solver, 3 to choose among up to 10 essential matrices and their 4 decompositions), so the
// iterations RANSAC needs grow as 1 / inlier_ratio^8: ~28k at 40 % inliers, hopeless at the 25 %
// that verification must accept. This subclass draws the minimal 5 and chooses among the
// essential matrices by their support over all correspondences (Sampson errors, cheap), then
// among the 4 decompositions by cheirality of the sample. OpenGV's distance function, sampler
// and Ransac loop are used unchanged.
class MinimalSampleProblem : public SacProblem {
 public:
  MinimalSampleProblem(adapter_t& adapter, algorithm_t algorithm, double max_error_rad)
      : SacProblem(adapter, algorithm, /*randomSeed=*/false), max_error_rad_(max_error_rad) {}

  int getSampleSize() const override { return 5; }

  bool computeModelCoefficients(const std::vector<int>& sample, model_t& model) const override {
    // OpenGV's essential matrices satisfy b_i^T E b_j = 0 (viewpoint 1 = i); ours is E^T.
    std::vector<Eigen::Matrix3d> essentials;
    if (_algorithm == NISTER) {
      for (const opengv::essential_t& E : opengv::relative_pose::fivept_nister(_adapter, sample)) {
        essentials.push_back(E.transpose());
      }
    } else {
      for (const opengv::complexEssential_t& E : opengv::relative_pose::fivept_stewenius(_adapter, sample)) {
        if (E.imag().norm() <= 1e-8 * E.real().norm()) essentials.push_back(E.real().transpose());
      }
    }
    int best_support = -1;
    for (const Eigen::Matrix3d& E : essentials) {
      if (!E.allFinite()) continue;
      const RelativePose pose = ChooseBySampleCheirality(RelativePoseFromEssential(E), sample);
      const int support = CountSupport(pose);
      if (support > best_support) {
        best_support = support;
        model = RelativePoseToOpenGV(pose);
      }
    }
    return best_support >= 0;
  }

 private:
  RelativePose ChooseBySampleCheirality(const RelativePose& pose, const std::vector<int>& sample) const {
    RelativePose best = pose;
    int best_in_front = -1;
    for (const RelativePose& candidate : EssentialPoseCandidates(pose)) {
      int in_front = 0;
      for (const int k : sample) {
        const auto point = TriangulateTwoView(candidate, _adapter.getBearingVector1(k), _adapter.getBearingVector2(k));
        in_front += point && point->depth_i > 0.0 && point->depth_j > 0.0;
      }
      if (in_front > best_in_front) {
        best_in_front = in_front;
        best = candidate;
      }
    }
    return best;
  }

  int CountSupport(const RelativePose& pose) const {
    int support = 0;
    for (const int k : *getIndices()) {
      support += AngularEpipolarError(pose, _adapter.getBearingVector1(k), _adapter.getBearingVector2(k)) <= max_error_rad_;
    }
    return support;
  }

  double max_error_rad_;
};

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

// Sum over every correspondence of min(e^2, truncation^2), e the angular epipolar error (MSAC's
// score): a model that fits its inliers more tightly costs less.
double TruncatedQuadraticCost(const RelativePose& pose, const std::vector<Eigen::Vector3d>& bearings_i,
                              const std::vector<Eigen::Vector3d>& bearings_j, double truncation_rad) {
  double cost = 0.0;
  for (size_t k = 0; k < bearings_i.size(); ++k) {
    const double error = AngularEpipolarError(pose, bearings_i[k], bearings_j[k]);
    cost += std::min(error * error, truncation_rad * truncation_rad);
  }
  return cost;
}

// RANSAC, cheirality, refinement and inlier selection at options.max_angular_error_deg.
RelativePoseResult EstimateAtThreshold(const std::vector<Eigen::Vector3d>& bearings_i,
                                       const std::vector<Eigen::Vector3d>& bearings_j,
                                       const RelativePoseOptions& options) {
  if (bearings_i.size() != bearings_j.size()) return FailedResult<RelativePoseResult>("bearing arrays differ in size");
  const opengv::bearingVectors_t opengv_i = ToOpenGVVectors(bearings_i);
  const opengv::bearingVectors_t opengv_j = ToOpenGVVectors(bearings_j);
  // View i is OpenGV's viewpoint 1 (see opengv_boundary.hpp). The adapter keeps references.
  opengv::relative_pose::CentralRelativeAdapter adapter(opengv_i, opengv_j);
  const auto algorithm = options.solver == RelativePoseOptions::Solver::kNister ? SacProblem::NISTER
                                                                                : SacProblem::STEWENIUS;
  const double max_error_rad = DegToRad(options.max_angular_error_deg);
  // make_shared, never new: see docs/dependencies.md §0 (aligned operator delete in libopengv).
  const auto problem = std::make_shared<MinimalSampleProblem>(adapter, algorithm, max_error_rad);
  // Checked here because OpenGV prints to stderr instead of failing when the sample is too big.
  if (bearings_i.size() < static_cast<size_t>(problem->getSampleSize())) {
    return FailedResult<RelativePoseResult>("too few correspondences: " + std::to_string(bearings_i.size()) + " < " +
                   std::to_string(problem->getSampleSize()));
  }
  const OpenGVRansacOutcome ransac =
      RunOpenGVRansac(problem, max_error_rad, options.ransac);
  if (!ransac.found) return FailedResult<RelativePoseResult>("RANSAC found no model");

  RelativePose pose = RelativePoseFromOpenGV(ransac.model);
  if (!(pose.translation.norm() > 0.0) || !pose.rotation.allFinite()) return FailedResult<RelativePoseResult>("RANSAC model is degenerate");
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
  result.num_ransac_iterations = ransac.num_iterations;
  result.num_inliers = static_cast<int>(set.inliers.size());
  result.num_inliers_in_front = set.num_in_front;
  result.inliers = std::move(set.inliers);
  // The uncertainty of the pose as returned: a refinement of no iteration only evaluates it.
  RelativePoseRefinementOptions evaluate_only;
  evaluate_only.max_num_iterations = 0;
  RelativePose evaluated = pose;
  result.rotation_std_deg =
      RadToDeg(RefineRelativePose(bearings_i, bearings_j, result.inliers, evaluate_only, &evaluated).RotationStdRad());
  if (result.num_inliers < 5) {
    result.reason = "too few inliers after refinement: " + std::to_string(result.num_inliers);
    return result;
  }
  result.success = true;
  return result;
}

}  // namespace

RelativePoseResult EstimateRelativePose(const std::vector<Eigen::Vector3d>& bearings_i,
                                        const std::vector<Eigen::Vector3d>& bearings_j,
                                        const RelativePoseOptions& options) {
  options.Check();
  RelativePoseResult loose = EstimateAtThreshold(bearings_i, bearings_j, options);
  const double ratio = options.precision_check_ratio;
  if (!loose.success || !(ratio > 0.0 && ratio < 1.0)) return loose;
  RelativePoseOptions tight_options = options;
  tight_options.max_angular_error_deg *= ratio;
  RelativePoseResult tight = EstimateAtThreshold(bearings_i, bearings_j, tight_options);
  tight.num_ransac_iterations += loose.num_ransac_iterations;
  loose.num_ransac_iterations = tight.num_ransac_iterations;
  if (!tight.success) return loose;
  const double truncation = DegToRad(tight_options.max_angular_error_deg);
  if (!(TruncatedQuadraticCost(tight.relative_pose, bearings_i, bearings_j, truncation) <
        TruncatedQuadraticCost(loose.relative_pose, bearings_i, bearings_j, truncation))) {
    return loose;
  }
  InlierSet set = SelectInliers(tight.relative_pose, bearings_i, bearings_j, DegToRad(options.max_angular_error_deg),
                                options.reject_points_behind);
  tight.num_inliers = static_cast<int>(set.inliers.size());
  tight.num_inliers_in_front = set.num_in_front;
  tight.inliers = std::move(set.inliers);
  return tight;
}

void RelativePoseOptions::Check() const {
  // The angle between a bearing and an epipolar plane is at most 90 degrees.
  RequirePositiveAtMost(max_angular_error_deg, 90.0, "RelativePoseOptions::max_angular_error_deg");
  ransac.Check();
  RequireAtLeast(refinement_rounds, 0, "RelativePoseOptions::refinement_rounds");
  // 0 = off; a ratio of 1 would repeat the same estimate, and EstimateRelativePose skips it.
  RequireInRange(precision_check_ratio, 0.0, 1.0, "RelativePoseOptions::precision_check_ratio");
}

}  // namespace sfm_pruning
