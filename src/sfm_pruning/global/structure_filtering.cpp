#include "sfm_pruning/global/structure_filtering.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <cmath>
#include <vector>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/global/bundle_observations.hpp"

namespace sfm_pruning {
namespace {

// Removes the failing posed observations of `landmark`, recording them in `removed`.
void FilterObservations(const StructureFilteringOptions& options, const SfmData& data, Landmark* landmark,
                        Landmark* removed, StructureFilteringResult* result) {
  for (const PosedObservation& obs : PosedObservationsOf(data, *landmark)) {
    const double error = ReprojectionErrorPx(obs, landmark->X);
    if (std::isfinite(error) && error <= options.max_reprojection_error_px) continue;
    ++(std::isfinite(error) ? result->num_observations_removed_error : result->num_observations_removed_behind);
    removed->observations[obs.view_id] = *obs.observation;
    landmark->observations.erase(obs.view_id);  // obs points into the map: it is not used again
  }
}

double MaxTriangulationAngleDeg(const std::vector<PosedObservation>& posed, const Eigen::Vector3d& X) {
  std::vector<Eigen::Vector3d> centers;
  centers.reserve(posed.size());
  for (const PosedObservation& obs : posed) centers.push_back(obs.pose->center);
  return RadToDeg(MaxTriangulationAngle(centers, X));
}

}  // namespace

StructureFilteringResult FilterStructure(const StructureFilteringOptions& options, SfmData* sfm_data) {
  StructureFilteringResult result;
  for (auto it = sfm_data->structure.begin(); it != sfm_data->structure.end();) {
    const IndexT landmark_id = it->first;
    Landmark& landmark = it->second;
    Landmark removed;
    removed.X = landmark.X;
    removed.color = landmark.color;
    FilterObservations(options, *sfm_data, &landmark, &removed, &result);

    const std::vector<PosedObservation> posed = PosedObservationsOf(*sfm_data, landmark);
    bool drop = false;
    if (posed.size() < options.min_num_observations) {
      ++result.num_landmarks_removed_few_observations;
      drop = true;
    } else if (MaxTriangulationAngleDeg(posed, landmark.X) < options.min_triangulation_angle_deg) {
      ++result.num_landmarks_removed_angle;
      drop = true;
    }
    if (drop) {
      removed.observations.insert(landmark.observations.begin(), landmark.observations.end());
      result.removed[landmark_id] = std::move(removed);
      it = sfm_data->structure.erase(it);
      continue;
    }
    if (!removed.observations.empty()) result.removed[landmark_id] = std::move(removed);
    ++result.num_landmarks_kept;
    result.num_observations_kept += posed.size();
    ++it;
  }
  return result;
}

void StructureFilteringOptions::Check() const {
  // 0 px would remove every observation; the angle is between two rays (0: any angle).
  RequirePositiveAtMost(max_reprojection_error_px, 1e6,
                        "StructureFilteringOptions::max_reprojection_error_px");
  RequireInRange(min_triangulation_angle_deg, 0.0, 180.0,
                 "StructureFilteringOptions::min_triangulation_angle_deg");
  // One observation cannot fix a point.
  RequireAtLeast<size_t>(min_num_observations, 2, "StructureFilteringOptions::min_num_observations");
}

}  // namespace sfm_pruning
