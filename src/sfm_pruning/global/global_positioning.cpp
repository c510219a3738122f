#include "sfm_pruning/global/global_positioning.hpp"

#include <algorithm>
#include <set>

namespace sfm_pruning {

PositioningResult PositionCamerasAndPoints(const GlobalPositioningOptions& options,
                                           const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                           const std::vector<Track>& tracks, const FeaturesPerView& features,
                                           SfmData* sfm_data) {
  PositioningResult result;
  result.message = CheckOnePosePerView(*sfm_data, rotations);
  if (!result.message.empty()) return result;
  const std::vector<PositioningTrack> rays = MakePositioningTracks(*sfm_data, features, rotations, tracks);
  if (rays.empty()) {
    result.message = "no track is seen by two positionable views";
    return result;
  }

  // Unknowns: the cameras (increasing view id, so index 0 is the gauge camera), then the points.
  std::set<IndexT> camera_set;
  for (const PositioningTrack& track : rays) {
    for (const PositioningObservation& observation : track.observations) camera_set.insert(observation.view_id);
  }
  const std::vector<IndexT> cameras(camera_set.begin(), camera_set.end());
  const auto camera_index = [&](IndexT view_id) {
    return static_cast<size_t>(std::lower_bound(cameras.begin(), cameras.end(), view_id) - cameras.begin());
  };
  std::vector<RayConstraint> constraints;
  for (size_t t = 0; t < rays.size(); ++t) {
    for (const PositioningObservation& observation : rays[t].observations) {
      constraints.push_back({camera_index(observation.view_id), cameras.size() + t, observation.ray_world});
    }
  }

  std::vector<Eigen::Vector3d> positions;
  if (!SolveFromRandomStart(options.solver, cameras.size() + rays.size(), constraints, "global_positioning",
                            &positions, &result)
           .usable) {
    return result;
  }

  std::map<IndexT, Eigen::Vector3d> centers;
  for (size_t c = 0; c < cameras.size(); ++c) centers[cameras[c]] = positions[c];
  std::vector<std::optional<Eigen::Vector3d>> points(positions.begin() + static_cast<std::ptrdiff_t>(cameras.size()),
                                                     positions.end());
  WritePositionedScene(rotations, centers, rays, points, options.max_angular_residual_deg, sfm_data, &result);
  result.success = true;
  return result;
}

}  // namespace sfm_pruning
