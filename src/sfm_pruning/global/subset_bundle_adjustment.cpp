#include "sfm_pruning/global/subset_bundle_adjustment.hpp"

#include <chrono>
#include <vector>

#include "sfm_pruning/global/bundle_observations.hpp"

namespace sfm_pruning {

BundleAdjustmentResult AdjustBundleOnSubset(const BundleAdjustmentOptions& bundle,
                                            const TrackSubsamplingOptions& subsampling,
                                            const RetriangulationOptions& retriangulation, SfmData* sfm_data) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<IndexT> landmark_ids;
  std::vector<SampledTrack> sampled;
  for (const auto& [landmark_id, landmark] : sfm_data->structure) {
    SampledTrack track;
    for (const PosedObservation& observation : PosedObservationsOf(*sfm_data, landmark)) {
      track.push_back({observation.view_id, observation.observation->x});
    }
    landmark_ids.push_back(landmark_id);
    sampled.push_back(std::move(track));
  }
  const std::vector<size_t> selected = SelectWellDistributedTracks(sampled, subsampling);
  if (selected.size() == landmark_ids.size()) return AdjustBundle(bundle, sfm_data);

  SfmData subset;
  subset.views = sfm_data->views;
  subset.intrinsics = sfm_data->intrinsics;
  subset.poses = sfm_data->poses;
  for (const size_t k : selected) subset.structure.emplace(landmark_ids[k], sfm_data->structure.at(landmark_ids[k]));
  BundleAdjustmentResult result = AdjustBundle(bundle, &subset);
  if (!result.success) return result;

  sfm_data->poses = std::move(subset.poses);
  sfm_data->intrinsics = std::move(subset.intrinsics);
  for (const auto& [landmark_id, landmark] : subset.structure) sfm_data->structure.at(landmark_id).X = landmark.X;
  RetriangulationOptions points_only = retriangulation;
  points_only.complete_tracks = false;
  RetriangulateLandmarks(points_only, nullptr, sfm_data);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace sfm_pruning
