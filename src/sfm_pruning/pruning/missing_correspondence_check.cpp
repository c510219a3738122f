#include "sfm_pruning/pruning/missing_correspondence_check.hpp"

#include <cmath>
#include <map>
#include <utility>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// Median absolute deviation to the standard deviation of a normal distribution.
constexpr double kMadToSigma = 1.4826;

// The landmarks of the model, listed per view that observes them.
std::map<IndexT, std::vector<IndexT>> LandmarksPerView(const SfmData& model) {
  std::map<IndexT, std::vector<IndexT>> per_view;
  for (const auto& [landmark_id, landmark] : model.structure) {
    for (const auto& [view_id, observation] : landmark.observations) per_view[view_id].push_back(landmark_id);
  }
  return per_view;
}

// Whether a feature detector in `view` should find landmark X, which `observer` finds: X in front of
// the view and inside its image, seen from about the observer's direction and distance.
bool Predicted(const Eigen::Vector3d& X, const Pose& pose, const CameraIntrinsics& intrinsics,
               const Pose& observer, double min_cos_angle, double max_distance_ratio) {
  const Eigen::Vector3d X_camera = pose.ToCamera(X);
  if (!(X_camera.z() > 0.0)) return false;
  const Eigen::Vector2d pixel = intrinsics.Project(X_camera);
  if (!(pixel.x() >= 0.0 && pixel.y() >= 0.0 && pixel.x() < intrinsics.width() && pixel.y() < intrinsics.height())) {
    return false;
  }
  const Eigen::Vector3d from_view = X - pose.center;
  const Eigen::Vector3d from_observer = X - observer.center;
  const double distance = from_view.norm();
  const double observer_distance = from_observer.norm();
  if (!(distance > 0.0 && observer_distance > 0.0)) return false;
  if (distance > max_distance_ratio * observer_distance || observer_distance > max_distance_ratio * distance) {
    return false;
  }
  return from_view.dot(from_observer) >= min_cos_angle * distance * observer_distance;
}

// The landmarks of `observer_id` predicted in `view_id`, and those `view_id` observes.
ObservedLandmarks CountOneDirection(const SfmData& model, const std::map<IndexT, std::vector<IndexT>>& per_view,
                                    IndexT observer_id, IndexT view_id, const MissingCorrespondenceOptions& options) {
  ObservedLandmarks share;
  const auto observed_by = per_view.find(observer_id);
  if (observed_by == per_view.end()) return share;
  const View& view = model.views.at(view_id);
  const Pose& pose = model.PoseOf(view);
  const Pose& observer = model.PoseOf(model.views.at(observer_id));
  const CameraIntrinsics& intrinsics = model.IntrinsicsOf(view);
  const double min_cos_angle = std::cos(DegToRad(options.max_viewing_angle_deg));
  for (const IndexT landmark_id : observed_by->second) {
    const Landmark& landmark = model.structure.at(landmark_id);
    if (!Predicted(landmark.X, pose, intrinsics, observer, min_cos_angle, options.max_distance_ratio)) continue;
    ++share.predicted;
    share.observed += landmark.observations.count(view_id);
  }
  return share;
}

}  // namespace

std::vector<EdgeObservedShare> MeasureObservedShares(const SfmData& model, const std::vector<ViewPair>& edges,
                                                     const MissingCorrespondenceOptions& options) {
  const std::map<IndexT, std::vector<IndexT>> per_view = LandmarksPerView(model);
  std::vector<EdgeObservedShare> shares;
  for (const ViewPair& pair : edges) {
    if (!model.IsPosed(pair.first) || !model.IsPosed(pair.second)) continue;
    EdgeObservedShare share;
    share.pair = pair;
    share.to_second = CountOneDirection(model, per_view, pair.first, pair.second, options);
    share.to_first = CountOneDirection(model, per_view, pair.second, pair.first, options);
    shares.push_back(share);
  }
  return shares;
}

MissingCorrespondenceRound JudgeObservedShares(std::vector<EdgeObservedShare> edges,
                                               const MissingCorrespondenceOptions& options) {
  MissingCorrespondenceRound round;
  round.edges = std::move(edges);
  std::vector<double> judged;
  for (const EdgeObservedShare& edge : round.edges) {
    if (edge.MinPredicted() >= options.min_predicted_landmarks) judged.push_back(edge.Share());
  }
  round.num_judged = judged.size();
  // The spread needs a population of true edges; with a handful the median is not theirs.
  if (judged.size() < 2 * static_cast<size_t>(std::ceil(options.max_robust_deviations)) + 1) return round;
  round.median_share = Median(judged);
  std::vector<double> deviations;
  deviations.reserve(judged.size());
  for (const double share : judged) deviations.push_back(std::abs(share - round.median_share));
  const double sigma = kMadToSigma * Median(std::move(deviations));
  round.bound = round.median_share - options.max_robust_deviations * sigma;
  for (const EdgeObservedShare& edge : round.edges) {
    if (edge.MinPredicted() >= options.min_predicted_landmarks && edge.Share() < round.bound) {
      round.removed.push_back(edge.pair);
    }
  }
  return round;
}

void MissingCorrespondenceOptions::Check() const {
  RequireInRange<size_t>(max_rounds, 0, 100, "MissingCorrespondenceOptions::max_rounds");
  RequirePositiveAtMost(max_viewing_angle_deg, 90.0, "MissingCorrespondenceOptions::max_viewing_angle_deg");
  RequireInRange(max_distance_ratio, 1.0, 1e6, "MissingCorrespondenceOptions::max_distance_ratio");
  RequireAtLeast<size_t>(min_predicted_landmarks, 1, "MissingCorrespondenceOptions::min_predicted_landmarks");
  RequirePositiveAtMost(max_robust_deviations, 1e3, "MissingCorrespondenceOptions::max_robust_deviations");
}

}  // namespace sfm_pruning
