#include "sfm_pruning/eval/relative_pose_error.hpp"

#include <algorithm>
#include <limits>

namespace sfm_pruning {
namespace {

constexpr double kCoincidentCentersRelativeTolerance = 1e-12;

bool CentersCoincide(const Pose& a, const Pose& b) {
  const double scale = std::max(a.center.norm(), b.center.norm());
  return (a.center - b.center).norm() <= kCoincidentCentersRelativeTolerance * scale;
}

}  // namespace

RelativePoseError ComputeRelativePoseError(const Pose& true_i, const Pose& true_j, const Pose& estimated_i,
                                           const Pose& estimated_j) {
  const RelativePose truth = RelativePoseBetween(true_i, true_j);
  const RelativePose estimate = RelativePoseBetween(estimated_i, estimated_j);
  RelativePoseError error;
  error.rotation_deg = RadToDeg(RotationAngleBetween(truth.rotation, estimate.rotation));
  const bool true_coincident = CentersCoincide(true_i, true_j);
  const bool estimated_coincident = CentersCoincide(estimated_i, estimated_j);
  if (true_coincident || estimated_coincident) {
    error.translation_deg = true_coincident == estimated_coincident ? 0.0 : 180.0;
  } else {
    error.translation_deg = RadToDeg(AngleBetweenVectors(truth.translation, estimate.translation));
  }
  return error;
}

std::vector<double> PairwisePoseErrorsDeg(const std::vector<MatchedCamera>& cameras) {
  std::vector<double> errors;
  errors.reserve(cameras.size() * (cameras.size() - (cameras.empty() ? 0 : 1)) / 2);
  for (size_t i = 0; i < cameras.size(); ++i) {
    for (size_t j = i + 1; j < cameras.size(); ++j) {
      const MatchedCamera& a = cameras[i];
      const MatchedCamera& b = cameras[j];
      if (!a.estimate || !b.estimate) {
        errors.push_back(std::numeric_limits<double>::infinity());
        continue;
      }
      errors.push_back(ComputeRelativePoseError(a.ground_truth, b.ground_truth, *a.estimate, *b.estimate).MaxDeg());
    }
  }
  return errors;
}

}  // namespace sfm_pruning
