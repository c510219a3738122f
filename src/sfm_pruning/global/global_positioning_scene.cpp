#include "sfm_pruning/global/global_positioning_scene.hpp"

#include <algorithm>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

namespace {

// Seed of random start k: start 0 is the seed itself (one start reproduces the single solve);
// the others are spread by the 64-bit golden ratio, as splitmix64 spreads its states.
uint64_t StartSeed(uint64_t seed, int start) {
  return seed + static_cast<uint64_t>(start) * 0x9E3779B97F4A7C15ULL;
}

size_t CountConsistentConstraints(const std::vector<RayConstraint>& constraints,
                                  const std::vector<Eigen::Vector3d>& positions, double threshold_deg) {
  size_t count = 0;
  for (const RayConstraint& constraint : constraints) {
    if (RayConstraintResidualDeg(constraint, positions) <= threshold_deg) ++count;
  }
  return count;
}

}  // namespace

PositioningSolverSummary SolveFromRandomStart(const PositioningSolverOptions& options, size_t num_positions,
                                              const std::vector<RayConstraint>& constraints, const std::string& stage,
                                              std::vector<Eigen::Vector3d>* positions, PositioningResult* result) {
  const int num_starts = std::max(options.num_random_starts, 1);
  const bool screening = num_starts > 1 && options.start_screening_iterations > 0;
  PositioningSolverOptions start_options = options;
  if (screening) {
    start_options.max_num_iterations = options.start_screening_iterations;
    start_options.num_rejection_rounds = 0;
  }
  PositioningSolverSummary best;
  size_t best_consistent = 0;
  result->consistent_constraints_per_start.clear();
  for (int start = 0; start < num_starts; ++start) {
    std::vector<Eigen::Vector3d> candidate =
        RandomPositions(num_positions, options.init_cube_half_size, StartSeed(options.seed, start));
    const PositioningSolverSummary summary = SolveRayAlignment(start_options, constraints, 0, stage, &candidate);
    const size_t consistent =
        summary.usable ? CountConsistentConstraints(constraints, candidate, options.rejection_threshold_deg) : 0;
    result->consistent_constraints_per_start.push_back(consistent);
    const bool better = start == 0 || (summary.usable && !best.usable) ||
                        (summary.usable && (consistent > best_consistent ||
                                            (consistent == best_consistent && summary.final_cost < best.final_cost)));
    if (!better) continue;
    best = summary;
    best_consistent = consistent;
    *positions = std::move(candidate);
    result->selected_start = start;
  }
  if (screening && best.usable) {
    // The screened winner goes on for the iterations its screening left of the cap.
    PositioningSolverOptions rest = options;
    rest.max_num_iterations = std::max(options.max_num_iterations - options.start_screening_iterations, 1);
    const PositioningSolverSummary screened = best;
    best = SolveRayAlignment(rest, constraints, 0, stage, positions, true);
    best.num_iterations += screened.num_iterations;
    best.num_solves += screened.num_solves;
    best.initial_cost = screened.initial_cost;
  }
  result->num_random_starts = num_starts;
  result->message = best.termination;
  result->num_solver_iterations = best.num_iterations;
  result->initial_cost = best.initial_cost;
  result->final_cost = best.final_cost;
  return best;
}

double RayAngularResidualDeg(const PositioningObservation& observation, const Eigen::Vector3d& center,
                             const Eigen::Vector3d& point) {
  return RadToDeg(AngleBetweenVectors(observation.ray_world, point - center));
}

namespace {

// DLT point from the observations of views with a centre; with `reference`, only from those whose
// ray passes within max_angular_residual_deg of it.
std::optional<Eigen::Vector3d> TriangulateTrack(const PositioningTrack& track,
                                                const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                const std::map<IndexT, Eigen::Vector3d>& centers,
                                                double max_angular_residual_deg, TriangulationMethod method,
                                                const std::optional<Eigen::Vector3d>& reference) {
  std::vector<Pose> poses;
  std::vector<Eigen::Vector3d> bearings;
  for (const PositioningObservation& observation : track.observations) {
    const auto center = centers.find(observation.view_id);
    if (center == centers.end()) continue;
    if (reference && RayAngularResidualDeg(observation, center->second, *reference) > max_angular_residual_deg) {
      continue;
    }
    poses.emplace_back(rotations.at(observation.view_id), center->second);
    bearings.push_back(observation.bearing);
  }
  if (poses.size() < 2) return std::nullopt;
  return TriangulateMultiView(poses, bearings, method);
}

}  // namespace

std::vector<std::optional<Eigen::Vector3d>> TriangulateTracks(const std::vector<PositioningTrack>& tracks,
                                                              const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                              const std::map<IndexT, Eigen::Vector3d>& centers,
                                                              double max_angular_residual_deg,
                                                              TriangulationMethod method) {
  std::vector<std::optional<Eigen::Vector3d>> points;
  points.reserve(tracks.size());
  for (const PositioningTrack& track : tracks) {
    const std::optional<Eigen::Vector3d> first =
        TriangulateTrack(track, rotations, centers, max_angular_residual_deg, method, std::nullopt);
    const std::optional<Eigen::Vector3d> refined =
        first ? TriangulateTrack(track, rotations, centers, max_angular_residual_deg, method, first) : std::nullopt;
    points.push_back(refined ? refined : first);
  }
  return points;
}

void WritePositionedScene(const std::map<IndexT, Eigen::Matrix3d>& rotations,
                          const std::map<IndexT, Eigen::Vector3d>& centers,
                          const std::vector<PositioningTrack>& tracks,
                          const std::vector<std::optional<Eigen::Vector3d>>& points, double max_angular_residual_deg,
                          SfmData* sfm_data, PositioningResult* result) {
  sfm_data->poses.clear();
  sfm_data->structure.clear();
  for (const auto& [view_id, center] : centers) {
    sfm_data->poses[sfm_data->views.at(view_id).id_pose] = Pose(rotations.at(view_id), center);
  }
  result->num_positioned_views = centers.size();

  for (size_t t = 0; t < tracks.size(); ++t) {
    if (!points[t]) {
      ++result->num_dropped_tracks;
      continue;
    }
    Landmark landmark;
    landmark.X = *points[t];
    for (const PositioningObservation& observation : tracks[t].observations) {
      const auto center = centers.find(observation.view_id);
      if (center == centers.end()) continue;
      if (RayAngularResidualDeg(observation, center->second, landmark.X) > max_angular_residual_deg) {
        ++result->num_filtered_observations;
        continue;
      }
      landmark.observations[observation.view_id] = Observation{observation.pixel, observation.feature_id};
    }
    if (landmark.observations.size() < 2) {
      ++result->num_dropped_tracks;
      continue;
    }
    result->num_observations += landmark.observations.size();
    sfm_data->structure[static_cast<IndexT>(tracks[t].track_id)] = std::move(landmark);
  }
  result->num_landmarks = sfm_data->structure.size();
}

}  // namespace sfm_pruning
