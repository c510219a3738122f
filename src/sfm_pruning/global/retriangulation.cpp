#include "sfm_pruning/global/retriangulation.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/global/bundle_observations.hpp"

namespace sfm_pruning {
namespace {

// Sum of squared reprojection errors; +infinity when the point is behind any camera.
double SumSquaredErrors(const std::vector<PosedObservation>& posed, const Eigen::Vector3d& X) {
  double sum = 0.0;
  for (const PosedObservation& obs : posed) {
    const double error = ReprojectionErrorPx(obs, X);
    sum += error * error;
  }
  return sum;
}

double MaxErrorPx(const std::vector<PosedObservation>& posed, const Eigen::Vector3d& X) {
  double max_error = 0.0;
  for (const PosedObservation& obs : posed) max_error = std::max(max_error, ReprojectionErrorPx(obs, X));
  return max_error;
}

// DLT point of the posed observations, if it lies in front of every camera under enough angle.
std::optional<Eigen::Vector3d> Triangulate(const RetriangulationOptions& options,
                                           const std::vector<PosedObservation>& posed) {
  std::vector<Pose> poses;
  std::vector<Eigen::Vector3d> bearings;
  std::vector<Eigen::Vector3d> centers;
  for (const PosedObservation& obs : posed) {
    poses.push_back(*obs.pose);
    bearings.push_back(obs.intrinsics->Unproject(obs.observation->x));
    centers.push_back(obs.pose->center);
  }
  const std::optional<Eigen::Vector3d> X = TriangulateMultiView(poses, bearings);
  if (!X || !IsInFrontOfAll(poses, bearings, *X)) return std::nullopt;
  if (RadToDeg(MaxTriangulationAngle(centers, *X)) < options.min_triangulation_angle_deg) return std::nullopt;
  return X;
}

// Step 1 of the header comment on a landmark of the structure; true when X was replaced.
bool UpdatePoint(const RetriangulationOptions& options, const SfmData& data, Landmark* landmark) {
  const std::vector<PosedObservation> posed = PosedObservationsOf(data, *landmark);
  const std::optional<Eigen::Vector3d> X = Triangulate(options, posed);
  if (!X || !(SumSquaredErrors(posed, *X) <= SumSquaredErrors(posed, landmark->X))) return false;
  landmark->X = *X;
  return true;
}

// Step 2: adds back the removed observations that fit X; returns how many.
size_t CompleteTrack(const RetriangulationOptions& options, const SfmData& data, const Landmark& removed,
                     Landmark* landmark) {
  size_t num_added = 0;
  for (const PosedObservation& obs : PosedObservationsOf(data, removed)) {
    if (landmark->observations.count(obs.view_id)) continue;
    if (!(ReprojectionErrorPx(obs, landmark->X) <= options.max_reprojection_error_px)) continue;
    landmark->observations[obs.view_id] = *obs.observation;
    ++num_added;
  }
  return num_added;
}

// A landmark removed entirely: restored when all its posed observations agree on a point.
std::optional<Landmark> RestoreLandmark(const RetriangulationOptions& options, const SfmData& data,
                                        const Landmark& removed) {
  const std::vector<PosedObservation> posed = PosedObservationsOf(data, removed);
  const std::optional<Eigen::Vector3d> X = Triangulate(options, posed);
  if (!X || !(MaxErrorPx(posed, *X) <= options.max_reprojection_error_px)) return std::nullopt;
  Landmark restored = removed;
  restored.X = *X;
  return restored;
}

}  // namespace

RetriangulationResult RetriangulateLandmarks(const RetriangulationOptions& options,
                                             const std::map<IndexT, Landmark>* removed, SfmData* sfm_data) {
  RetriangulationResult result;
  for (auto& [landmark_id, landmark] : sfm_data->structure) {
    ++(UpdatePoint(options, *sfm_data, &landmark) ? result.num_landmarks_updated : result.num_landmarks_unchanged);
  }
  if (!options.complete_tracks || removed == nullptr) return result;
  for (const auto& [landmark_id, removed_landmark] : *removed) {
    const auto it = sfm_data->structure.find(landmark_id);
    if (it != sfm_data->structure.end()) {
      result.num_observations_restored += CompleteTrack(options, *sfm_data, removed_landmark, &it->second);
      continue;
    }
    if (std::optional<Landmark> restored = RestoreLandmark(options, *sfm_data, removed_landmark)) {
      result.num_observations_restored += PosedObservationsOf(*sfm_data, *restored).size();
      sfm_data->structure.emplace(landmark_id, std::move(*restored));
      ++result.num_landmarks_restored;
    }
  }
  return result;
}

void RetriangulationOptions::Check() const {
  // 0 px would restore nothing; the angle is between two rays (0: any angle).
  RequirePositiveAtMost(max_reprojection_error_px, 1e6, "RetriangulationOptions::max_reprojection_error_px");
  RequireInRange(min_triangulation_angle_deg, 0.0, 180.0,
                 "RetriangulationOptions::min_triangulation_angle_deg");
}

}  // namespace sfm_pruning
