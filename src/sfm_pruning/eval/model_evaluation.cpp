#include "sfm_pruning/eval/model_evaluation.hpp"

#include <cmath>

#include "sfm_pruning/eval/pose_auc.hpp"
#include "sfm_pruning/eval/relative_pose_error.hpp"
#include "sfm_pruning/util/statistics.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

std::optional<AlignmentErrors> AlignAndMeasure(const std::vector<MatchedCamera>& cameras,
                                               const RobustSimilarityOptions& options) {
  std::vector<const MatchedCamera*> registered;
  std::vector<Eigen::Vector3d> estimated_centers, true_centers;
  for (const MatchedCamera& camera : cameras) {
    if (!camera.estimate) continue;
    registered.push_back(&camera);
    estimated_centers.push_back(camera.estimate->center);
    true_centers.push_back(camera.ground_truth.center);
  }
  const std::optional<RobustSimilarity> fit = FitSimilarityRobust(estimated_centers, true_centers, options);
  if (!fit) return std::nullopt;

  AlignmentErrors errors;
  errors.transform = fit->transform;
  errors.num_inliers = fit->num_inliers;
  errors.inlier_threshold = fit->inlier_threshold;
  std::vector<double> position_errors, rotation_errors_deg;
  for (const MatchedCamera* camera : registered) {
    const Pose aligned = fit->transform.Apply(*camera->estimate);
    position_errors.push_back((aligned.center - camera->ground_truth.center).norm());
    rotation_errors_deg.push_back(RadToDeg(RotationAngleBetween(camera->ground_truth.rotation, aligned.rotation)));
  }
  errors.median_position_error = Median(position_errors);
  errors.mean_position_error = Mean(position_errors);
  errors.median_rotation_error_deg = Median(rotation_errors_deg);
  errors.mean_rotation_error_deg = Mean(rotation_errors_deg);
  return errors;
}

}  // namespace

EvaluationReport EvaluateMatchedCameras(const CameraMatching& matching, const EvaluationOptions& options) {
  options.Check();
  EvaluationReport report;
  report.num_ground_truth_images = matching.cameras.size();
  report.num_registered_images = matching.NumRegistered();
  report.num_estimate_images = matching.num_estimate_images;
  report.num_unmatched_estimate_images = matching.num_unmatched_estimate_images;

  const std::vector<double> errors = PairwisePoseErrorsDeg(matching.cameras);
  report.num_pairs = errors.size();
  for (double error : errors) report.num_failed_pairs += std::isinf(error) ? 1 : 0;
  const std::vector<double> aucs = AucPercent(errors, options.auc_thresholds_deg);
  for (size_t k = 0; k < aucs.size(); ++k) report.auc.push_back({options.auc_thresholds_deg[k], aucs[k]});

  report.alignment = AlignAndMeasure(matching.cameras, options.alignment);
  return report;
}

EvaluationReport EvaluateModel(const SfmData& estimate, const SfmData& ground_truth, const EvaluationOptions& options,
                               const std::string& estimate_source, const std::string& ground_truth_source) {
  options.Check();  // before the cameras are matched
  const CameraMatching matching = MatchCamerasByName(estimate, ground_truth, estimate_source, ground_truth_source);
  if (matching.cameras.size() < 2) {
    throw FileError(ground_truth_source, "fewer than 2 posed images (" + std::to_string(matching.cameras.size()) +
                                             "), no pair to evaluate");
  }
  if (matching.NumRegistered() == 0) {
    throw FileError(estimate_source, "no posed image name in common with " + ground_truth_source + " (estimate: " +
                                         std::to_string(matching.num_estimate_images) +
                                         " posed image names, ground truth: " +
                                         std::to_string(matching.cameras.size()) + ")");
  }
  return EvaluateMatchedCameras(matching, options);
}

void EvaluationOptions::Check() const {
  // What AucPercent (pose_auc.hpp) integrates up to; an empty list reports no AUC.
  for (size_t k = 0; k < auc_thresholds_deg.size(); ++k) {
    RequirePositiveFinite(auc_thresholds_deg[k], "EvaluationOptions::auc_thresholds_deg[" + std::to_string(k) + "]");
  }
  alignment.Check();
}

}  // namespace sfm_pruning
