#include "sfm_pruning/global/global_positioning.hpp"

#include <algorithm>
#include <set>

namespace sfm_pruning {

PositioningResult PositionCamerasAndPoints(const GlobalPositioningOptions& options,
                                           const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                           const std::vector<Track>& tracks, const FeaturesPerView& features,
                                           SfmData* sfm_data, const std::vector<Track>* solve_tracks) {
  PositioningResult result;
  result.message = CheckOnePosePerView(*sfm_data, rotations);
  if (!result.message.empty()) return result;
  const std::vector<PositioningTrack> rays = MakePositioningTracks(*sfm_data, features, rotations, tracks);
  const std::vector<PositioningTrack> solve_rays =
      solve_tracks != nullptr ? MakePositioningTracks(*sfm_data, features, rotations, *solve_tracks)
                              : std::vector<PositioningTrack>{};
  const std::vector<PositioningTrack>& solved_rays = solve_tracks != nullptr ? solve_rays : rays;
  if (rays.empty() || solved_rays.empty()) {
    result.message = "no track is seen by two positionable views";
    return result;
  }

  // Unknowns: the cameras (increasing view id, so index 0 is the gauge camera), then the points of
  // the solved tracks. Every camera of `solved_rays` observes a solved track (the subsampling gives
  // each view at least one).
  std::vector<SampledTrack> sampled(solved_rays.size());
  for (size_t t = 0; t < solved_rays.size(); ++t) {
    for (const PositioningObservation& observation : solved_rays[t].observations) {
      sampled[t].push_back({observation.view_id, observation.pixel});
    }
  }
  const std::vector<size_t> solved = SelectWellDistributedTracks(sampled, options.subsampling);
  result.num_solved_tracks = solved.size();
  std::set<IndexT> camera_set;
  for (const size_t t : solved) {
    for (const PositioningObservation& observation : solved_rays[t].observations) camera_set.insert(observation.view_id);
  }
  const std::vector<IndexT> cameras(camera_set.begin(), camera_set.end());
  const auto camera_index = [&](IndexT view_id) {
    return static_cast<size_t>(std::lower_bound(cameras.begin(), cameras.end(), view_id) - cameras.begin());
  };
  std::vector<RayConstraint> constraints;
  for (size_t k = 0; k < solved.size(); ++k) {
    for (const PositioningObservation& observation : solved_rays[solved[k]].observations) {
      constraints.push_back({camera_index(observation.view_id), cameras.size() + k, observation.ray_world});
    }
  }

  std::vector<Eigen::Vector3d> positions;
  if (!SolveFromRandomStart(options.solver, cameras.size() + solved.size(), constraints, "global_positioning",
                            &positions, &result)
           .usable) {
    return result;
  }

  std::map<IndexT, Eigen::Vector3d> centers;
  for (size_t c = 0; c < cameras.size(); ++c) centers[cameras[c]] = positions[c];
  // The solve's own points, when it solved the structure's tracks; the other tracks are triangulated.
  std::vector<std::optional<Eigen::Vector3d>> points(rays.size());
  std::vector<bool> is_solved(rays.size(), false);
  for (size_t k = 0; solve_tracks == nullptr && k < solved.size(); ++k) {
    points[solved[k]] = positions[cameras.size() + k];
    is_solved[solved[k]] = true;
  }
  std::vector<PositioningTrack> others;
  for (size_t t = 0; t < rays.size(); ++t) {
    if (!is_solved[t]) others.push_back(rays[t]);
  }
  const std::vector<std::optional<Eigen::Vector3d>> triangulated =
      TriangulateTracks(others, rotations, centers, options.max_angular_residual_deg, TriangulationMethod::kDlt);
  for (size_t t = 0, k = 0; t < rays.size(); ++t) {
    if (!is_solved[t]) points[t] = triangulated[k++];
  }
  WritePositionedScene(rotations, centers, rays, points, options.max_angular_residual_deg, sfm_data, &result);
  result.success = true;
  return result;
}

}  // namespace sfm_pruning
