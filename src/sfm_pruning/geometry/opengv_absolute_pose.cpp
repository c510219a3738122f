#include "sfm_pruning/geometry/opengv_absolute_pose.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <string>

#include <opengv/absolute_pose/CentralAbsoluteAdapter.hpp>
#include <opengv/sac_problems/absolute_pose/AbsolutePoseSacProblem.hpp>

#include "sfm_pruning/geometry/opengv_boundary.hpp"
#include "sfm_pruning/geometry/opengv_ransac.hpp"
#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

using SacProblem = opengv::sac_problems::absolute_pose::AbsolutePoseSacProblem;

// OpenGV's EPnP (modules::Epnp::qr_solve, Debian's libopengv 1.0) keeps its QR work buffers in
// function-static storage: concurrent solves share them, which changed results in the last digits
// and, when two threads made the very first call together, wrote through a null buffer (segfault).
// Every EPnP model fit of the process goes through one mutex; sampling, scoring and the nonlinear
// refinement still run in parallel. Kneip's P3P has no such state.
class SerializedEpnpProblem : public SacProblem {
 public:
  using SacProblem::SacProblem;

  bool computeModelCoefficients(const std::vector<int>& indices, model_t& out_model) const override {
    if (_algorithm != EPNP) return SacProblem::computeModelCoefficients(indices, out_model);
    static std::mutex epnp_mutex;
    const std::lock_guard<std::mutex> lock(epnp_mutex);
    return SacProblem::computeModelCoefficients(indices, out_model);
  }
};

// Correspondences whose point lies in front of the camera within the angular threshold.
std::vector<int> SelectInliers(const Pose& pose, const std::vector<Eigen::Vector3d>& bearings,
                               const std::vector<Eigen::Vector3d>& points_world, double max_error_rad) {
  std::vector<int> inliers;
  for (size_t k = 0; k < bearings.size(); ++k) {
    const Eigen::Vector3d point_camera = pose.ToCamera(points_world[k]);
    if (IsInFront(pose, bearings[k], points_world[k]) &&
        AngleBetweenVectors(point_camera, bearings[k]) <= max_error_rad) {
      inliers.push_back(static_cast<int>(k));
    }
  }
  return inliers;
}

}  // namespace

double AbsolutePoseThresholdRad(const AbsolutePoseOptions& options) {
  if (options.max_reprojection_error_px > 0.0 && options.focal_length_px > 0.0) {
    return std::atan(options.max_reprojection_error_px / options.focal_length_px);
  }
  return DegToRad(options.max_angular_error_deg);
}

AbsolutePoseResult EstimateAbsolutePose(const std::vector<Eigen::Vector3d>& bearings,
                                        const std::vector<Eigen::Vector3d>& points_world,
                                        const AbsolutePoseOptions& options) {
  options.Check();
  if (bearings.size() != points_world.size()) return FailedResult<AbsolutePoseResult>("bearings and points differ in size");
  const opengv::bearingVectors_t opengv_bearings = ToOpenGVVectors(bearings);
  const opengv::points_t opengv_points = ToOpenGVVectors(points_world);
  opengv::absolute_pose::CentralAbsoluteAdapter adapter(opengv_bearings, opengv_points);  // keeps references
  const auto algorithm = options.solver == AbsolutePoseOptions::Solver::kP3pKneip ? SacProblem::KNEIP
                                                                                  : SacProblem::EPNP;
  // make_shared, never new: see docs/dependencies.md §0 (aligned operator delete in libopengv).
  const auto problem = std::make_shared<SerializedEpnpProblem>(adapter, algorithm, /*randomSeed=*/false);
  // Checked here because OpenGV prints to stderr instead of failing when the sample is too big.
  const size_t needed = std::max<size_t>(problem->getSampleSize(), options.min_num_inliers);
  if (bearings.size() < needed) {
    return FailedResult<AbsolutePoseResult>("too few correspondences: " + std::to_string(bearings.size()) + " < " + std::to_string(needed));
  }
  const double max_error_rad = AbsolutePoseThresholdRad(options);
  const OpenGVRansacOutcome ransac =
      RunOpenGVRansac(problem, max_error_rad, options.ransac);
  if (!ransac.found) return FailedResult<AbsolutePoseResult>("RANSAC found no model");

  Pose pose = PoseFromOpenGV(ransac.model);
  std::vector<int> inliers = SelectInliers(pose, bearings, points_world, max_error_rad);
  for (int round = 0; round < options.refinement_rounds; ++round) {
    if (inliers.size() < static_cast<size_t>(problem->getSampleSize())) break;
    opengv::transformation_t refined_coefficients;
    problem->optimizeModelCoefficients(inliers, PoseToOpenGV(pose), refined_coefficients);
    if (!refined_coefficients.allFinite()) break;
    const Pose refined = PoseFromOpenGV(refined_coefficients);
    std::vector<int> refined_inliers = SelectInliers(refined, bearings, points_world, max_error_rad);
    // Keep the refinement unless it loses a noticeable part of the support.
    if (refined_inliers.size() < inliers.size() * 95 / 100) break;
    pose = refined;
    inliers = std::move(refined_inliers);
  }

  AbsolutePoseResult result;
  result.pose = pose;
  result.num_ransac_iterations = ransac.num_iterations;
  result.num_inliers = static_cast<int>(inliers.size());
  result.inliers = std::move(inliers);
  if (result.num_inliers < options.min_num_inliers) {
    result.reason = "too few inliers: " + std::to_string(result.num_inliers) + " < " +
                    std::to_string(options.min_num_inliers);
    return result;
  }
  result.success = true;
  return result;
}

void AbsolutePoseOptions::Check() const {
  // The angle between a bearing and the direction to its point is at most 180 degrees.
  RequirePositiveAtMost(max_angular_error_deg, 180.0, "AbsolutePoseOptions::max_angular_error_deg");
  // 0 = no pixel threshold / focal length not known: the angular threshold applies.
  RequireAtLeast(max_reprojection_error_px, 0.0, "AbsolutePoseOptions::max_reprojection_error_px");
  RequireAtLeast(focal_length_px, 0.0, "AbsolutePoseOptions::focal_length_px");
  ransac.Check();
  RequireAtLeast(refinement_rounds, 0, "AbsolutePoseOptions::refinement_rounds");
  RequireAtLeast(min_num_inliers, 0, "AbsolutePoseOptions::min_num_inliers");
}

}  // namespace sfm_pruning
