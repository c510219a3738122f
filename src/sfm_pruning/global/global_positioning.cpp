#include "sfm_pruning/global/global_positioning.hpp"

#include "sfm_pruning/util/option_checks.hpp"

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
  // The subsampling picks the solved tracks from their pixels. Rays are made for every track of
  // `tracks` (each is solved or triangulated) and, with match stars, for the selected stars only:
  // they outnumber the tracks several times, and rays for all of them were most of the memory.
  const std::vector<Track>& candidates = solve_tracks != nullptr ? *solve_tracks : tracks;
  const std::vector<SampledTrack> pixels = PositionableTrackPixels(*sfm_data, features, rotations, candidates);
  std::vector<size_t> selected = SelectWellDistributedTracks(pixels, options.subsampling);
  // Without a cap every index comes back, also those of tracks with fewer than two positionable
  // observations, which MakePositioningTracks drops: the solve's k-th point must be the k-th
  // selected track.
  selected.erase(std::remove_if(selected.begin(), selected.end(), [&](size_t t) { return pixels[t].empty(); }),
                 selected.end());
  const std::vector<PositioningTrack> rays = MakePositioningTracks(*sfm_data, features, rotations, tracks);
  std::vector<size_t> ray_of_track(tracks.size(), rays.size());
  for (size_t r = 0; r < rays.size(); ++r) ray_of_track[rays[r].track_id] = r;
  std::vector<PositioningTrack> star_rays;
  if (solve_tracks != nullptr) {
    std::vector<Track> selected_stars;
    selected_stars.reserve(selected.size());
    for (const size_t t : selected) selected_stars.push_back(candidates[t]);
    star_rays = MakePositioningTracks(*sfm_data, features, rotations, selected_stars);
  }
  std::vector<const PositioningTrack*> solved;  // the k-th is the k-th selected track
  for (size_t k = 0; k < selected.size(); ++k) {
    solved.push_back(solve_tracks != nullptr ? &star_rays[k] : &rays[ray_of_track[selected[k]]]);
  }
  if (rays.empty() || solved.empty()) {
    result.message = "no track is seen by two positionable views";
    return result;
  }
  result.num_solved_tracks = solved.size();

  // Unknowns: the cameras of the solved tracks (increasing view id, so index 0 is the gauge camera),
  // then their points. The subsampling gives every view with a candidate track at least one.
  std::set<IndexT> camera_set;
  for (const PositioningTrack* track : solved) {
    for (const PositioningObservation& observation : track->observations) camera_set.insert(observation.view_id);
  }
  const std::vector<IndexT> cameras(camera_set.begin(), camera_set.end());
  const auto camera_index = [&](IndexT view_id) {
    return static_cast<size_t>(std::lower_bound(cameras.begin(), cameras.end(), view_id) - cameras.begin());
  };
  std::vector<RayConstraint> constraints;
  for (size_t k = 0; k < solved.size(); ++k) {
    for (const PositioningObservation& observation : solved[k]->observations) {
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
  for (size_t k = 0; solve_tracks == nullptr && k < selected.size(); ++k) {
    const size_t r = ray_of_track[selected[k]];
    points[r] = positions[cameras.size() + k];
    is_solved[r] = true;
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

PositioningResult TriangulateFromPoses(const GlobalPositioningOptions& options,
                                       const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                       const std::map<IndexT, Eigen::Vector3d>& centers,
                                       const std::vector<Track>& tracks, const FeaturesPerView& features,
                                       SfmData* sfm_data) {
  PositioningResult result;
  result.message = CheckOnePosePerView(*sfm_data, rotations);
  if (!result.message.empty()) return result;
  const std::vector<PositioningTrack> rays = MakePositioningTracks(*sfm_data, features, rotations, tracks);
  if (rays.empty()) {
    result.message = "no track is seen by two posed views";
    return result;
  }
  const std::vector<std::optional<Eigen::Vector3d>> points =
      TriangulateTracks(rays, rotations, centers, options.max_angular_residual_deg, TriangulationMethod::kDlt);
  WritePositionedScene(rotations, centers, rays, points, options.max_angular_residual_deg, sfm_data, &result);
  result.success = true;
  return result;
}

void GlobalPositioningOptions::Check() const {
  solver.Check();
  RequirePositiveAtMost(max_angular_residual_deg, 180.0,
                        "GlobalPositioningOptions::max_angular_residual_deg");
  subsampling.Check();
}

}  // namespace sfm_pruning
