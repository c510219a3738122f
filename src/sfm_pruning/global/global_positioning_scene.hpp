// The output side shared by both positioning methods: the result record, and writing camera
// centres + points into SfmData with the angular outlier filter.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/global/global_positioning_rays.hpp"
#include "sfm_pruning/global/global_positioning_solver.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct PositioningResult {
  bool success = false;
  std::string message;  // why it failed, or the solver's termination message

  size_t num_positioned_views = 0;  // poses written
  size_t num_landmarks = 0;         // landmarks written
  size_t num_observations = 0;      // observations written
  // Observations whose ray misses its point by more than the angular threshold.
  size_t num_filtered_observations = 0;
  // Tracks with no landmark: no point, or fewer than two observations left after the filter.
  size_t num_dropped_tracks = 0;

  size_t num_solved_tracks = 0;  // tracks whose points the solver estimated (the rest: triangulated)
  int num_solver_iterations = 0;  // the kept start's
  double initial_cost = 0.0;  // solver cost (0.5 * sum of robustified squared residuals), kept start
  double final_cost = 0.0;
  // Random starts solved, the one kept (0 = the start from the seed itself) and, per start, the
  // solve's constraints that agree with its solution (within the rejection threshold).
  int num_random_starts = 0;
  int selected_start = 0;
  std::vector<size_t> consistent_constraints_per_start;
};

// Both methods' solve: positions from a random start (options.seed), SolveRayAlignment with
// position 0 (the smallest view id) as the translation gauge, and the solver's record (message,
// iterations, costs) copied into `result`. With options.num_random_starts = n > 1 it solves from n
// starts (start k seeded from seed and k) and keeps the usable one whose solution agrees
// with the most constraints (ray within rejection_threshold_deg); ties go to the lower final
// cost, then to the earlier start. Deterministic for a seed.
PositioningSolverSummary SolveFromRandomStart(const PositioningSolverOptions& options, size_t num_positions,
                                              const std::vector<RayConstraint>& constraints, const std::string& stage,
                                              std::vector<Eigen::Vector3d>* positions, PositioningResult* result);

// Angle in degrees between an observation's world ray and the direction from the camera centre to
// the point (180 for a point behind the camera, whatever the camera model).
double RayAngularResidualDeg(const PositioningObservation& observation, const Eigen::Vector3d& center,
                             const Eigen::Vector3d& point);

// One point per track from the cameras: a DLT (`method`) over the observations of views with a
// centre, then again over only those whose ray passes within max_angular_residual_deg of that
// first point (a DLT is least squares, so one outlier drags it, and the angular filter would then
// blame good observations). Empty where fewer than two observations remain or it is degenerate.
// Used for every track by translation averaging and, by global positioning, for the tracks left
// out of its solve.
std::vector<std::optional<Eigen::Vector3d>> TriangulateTracks(const std::vector<PositioningTrack>& tracks,
                                                              const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                              const std::map<IndexT, Eigen::Vector3d>& centers,
                                                              double max_angular_residual_deg,
                                                              TriangulationMethod method);

// Replaces sfm_data->poses and sfm_data->structure: one pose (rotation from `rotations`, centre
// from `centers`) per view of `centers`, under the view's id_pose; one landmark per track with a
// point, keyed by PositioningTrack::track_id, holding the observations of views with a centre
// whose RayAngularResidualDeg is at most `max_angular_residual_deg`, if at least two remain.
// Fills the counts of `result`.
void WritePositionedScene(const std::map<IndexT, Eigen::Matrix3d>& rotations,
                          const std::map<IndexT, Eigen::Vector3d>& centers,
                          const std::vector<PositioningTrack>& tracks,
                          const std::vector<std::optional<Eigen::Vector3d>>& points, double max_angular_residual_deg,
                          SfmData* sfm_data, PositioningResult* result);

}  // namespace sfm_pruning
