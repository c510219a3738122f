// Evaluation of an estimated reconstruction against ground truth: the numbers `prunesfm
// evaluate` reports. Cameras are matched by image basename (camera_matching.hpp).
//   - registered / total ground-truth images;
//   - AUC of the pairwise relative pose error at each threshold (relative_pose_error.hpp,
//     pose_auc.hpp), over all pairs of ground-truth images, failures included;
//   - after a robust similarity alignment of the camera centres (similarity_alignment.hpp),
//     median and mean absolute position and rotation errors over the registered images.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sfm_pruning/eval/camera_matching.hpp"
#include "sfm_pruning/eval/similarity_alignment.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct EvaluationOptions {
  std::vector<double> auc_thresholds_deg = {3.0, 5.0, 10.0};
  RobustSimilarityOptions alignment;  // carries the seed of the alignment's RANSAC

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct AucAtThreshold {
  double threshold_deg = 0.0;
  double auc_percent = 0.0;
};

struct AlignmentErrors {
  Similarity3 transform;          // estimate -> ground-truth frame
  size_t num_inliers = 0;         // cameras that agreed with the fitted alignment
  double inlier_threshold = 0.0;  // ground-truth units
  // Over all registered images, in ground-truth units and degrees.
  double median_position_error = 0.0;
  double mean_position_error = 0.0;
  double median_rotation_error_deg = 0.0;
  double mean_rotation_error_deg = 0.0;
};

struct EvaluationReport {
  size_t num_ground_truth_images = 0;
  size_t num_registered_images = 0;        // ground-truth images posed in the estimate
  size_t num_estimate_images = 0;          // posed images of the estimate
  size_t num_unmatched_estimate_images = 0;  // posed estimate images absent from ground truth
  size_t num_pairs = 0;                    // N (N - 1) / 2 over ground-truth images
  size_t num_failed_pairs = 0;             // pairs touching an unregistered image
  std::vector<AucAtThreshold> auc;
  std::optional<AlignmentErrors> alignment;  // empty when fewer than 3 usable cameras
};

// Evaluates an already matched set of cameras (what EvaluateModel does after matching).
EvaluationReport EvaluateMatchedCameras(const CameraMatching& matching, const EvaluationOptions& options = {});

// Matches by basename and evaluates. Throws Error naming both sources when no posed image of
// the estimate matches a ground-truth image, and when the ground truth has fewer than 2 posed
// images (no pair to measure).
EvaluationReport EvaluateModel(const SfmData& estimate, const SfmData& ground_truth,
                               const EvaluationOptions& options = {}, const std::string& estimate_source = "estimate",
                               const std::string& ground_truth_source = "ground truth");

}  // namespace sfm_pruning
