#include "sfm_pruning/global/translation_averaging.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <set>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {
namespace {

// The unknown centres (increasing view id, so index 0 is the gauge camera) and one direction
// constraint c_i -> c_j per usable edge.
struct DirectionProblem {
  std::vector<IndexT> cameras;
  std::vector<RayConstraint> constraints;
};

DirectionProblem MakeDirectionProblem(const ViewGraph& graph, const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                      const SfmData& sfm_data) {
  std::vector<std::pair<ViewPair, Eigen::Vector3d>> directions;
  std::set<IndexT> camera_set;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    if (!CanReceivePose(sfm_data, rotations, pair.first) || !CanReceivePose(sfm_data, rotations, pair.second)) return;
    const Eigen::Vector3d t_ij = edge.relative_pose.translation;
    if (t_ij.norm() == 0.0) return;  // no baseline, no direction
    directions.emplace_back(pair, (-rotations.at(pair.second).transpose() * t_ij).normalized());
    camera_set.insert(pair.first);
    camera_set.insert(pair.second);
  });
  DirectionProblem problem;
  problem.cameras.assign(camera_set.begin(), camera_set.end());
  const auto index_of = [&](IndexT view_id) {
    return static_cast<size_t>(std::lower_bound(problem.cameras.begin(), problem.cameras.end(), view_id) -
                               problem.cameras.begin());
  };
  for (const auto& [pair, direction] : directions) {
    problem.constraints.push_back({index_of(pair.first), index_of(pair.second), direction});
  }
  return problem;
}

}  // namespace

TranslationAveragingResult PositionCamerasByTranslationAveraging(const TranslationAveragingOptions& options,
                                                                 const ViewGraph& graph,
                                                                 const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                                 const std::vector<Track>& tracks,
                                                                 const FeaturesPerView& features, SfmData* sfm_data) {
  TranslationAveragingResult result;
  PositioningResult& positioning = result.positioning;
  positioning.message = CheckOnePosePerView(*sfm_data, rotations);
  if (!positioning.message.empty()) return result;
  const DirectionProblem problem = MakeDirectionProblem(graph, rotations, *sfm_data);
  result.num_edges = problem.constraints.size();
  if (problem.constraints.empty()) {
    positioning.message = "no valid edge between two views that can receive a pose";
    return result;
  }

  std::vector<Eigen::Vector3d> centers;
  const PositioningSolverSummary summary = SolveFromRandomStart(
      options.solver, problem.cameras.size(), problem.constraints, "translation_averaging", &centers, &positioning);
  result.num_rejected_edges = summary.num_rejected;
  if (!summary.usable) return result;

  std::map<IndexT, Eigen::Vector3d> center_of;
  for (size_t c = 0; c < problem.cameras.size(); ++c) center_of[problem.cameras[c]] = centers[c];
  const std::vector<PositioningTrack> rays = MakePositioningTracks(*sfm_data, features, rotations, tracks);
  const std::vector<std::optional<Eigen::Vector3d>> points =
      TriangulateTracks(rays, rotations, center_of, options.max_angular_residual_deg, options.triangulation);
  WritePositionedScene(rotations, center_of, rays, points, options.max_angular_residual_deg, sfm_data, &positioning);
  positioning.success = true;
  return result;
}

void TranslationAveragingOptions::Check() const {
  solver.Check();
  RequirePositiveAtMost(max_angular_residual_deg, 180.0,
                        "TranslationAveragingOptions::max_angular_residual_deg");
}

}  // namespace sfm_pruning
