#include "sfm_pruning/global/global_positioning_rays.hpp"

#include <set>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

// What a positionable view needs, looked up once per view instead of once per observation.
struct RayView {
  const CameraIntrinsics* intrinsics = nullptr;
  const FeatureSet* features = nullptr;
  Eigen::Matrix3d camera_to_world = Eigen::Matrix3d::Identity();
};

std::map<IndexT, RayView> PositionableViews(const SfmData& sfm_data, const FeaturesPerView& features,
                                            const std::map<IndexT, Eigen::Matrix3d>& rotations) {
  std::map<IndexT, RayView> views;
  for (const auto& [view_id, rotation] : rotations) {
    if (!CanReceivePose(sfm_data, rotations, view_id)) continue;
    const auto intrinsics = sfm_data.intrinsics.find(sfm_data.views.at(view_id).id_intrinsic);
    const auto feature_set = features.find(view_id);
    if (intrinsics == sfm_data.intrinsics.end() || feature_set == features.end()) continue;
    views[view_id] = {&intrinsics->second, &feature_set->second, rotation.transpose()};
  }
  return views;
}

// The feature's raw pixel; throws Error when the view has no such feature.
Eigen::Vector2d CheckedPosition(const RayView& view, size_t track_id, IndexT view_id, IndexT feature_id) {
  if (feature_id >= view.features->size()) {
    throw Error("track " + std::to_string(track_id) + ": view " + std::to_string(view_id) + " has no feature " +
                std::to_string(feature_id));
  }
  return view.features->Position(feature_id);
}

}  // namespace

bool CanReceivePose(const SfmData& sfm_data, const std::map<IndexT, Eigen::Matrix3d>& rotations, IndexT view_id) {
  const auto view = sfm_data.views.find(view_id);
  return view != sfm_data.views.end() && view->second.id_pose != kUndefinedIndex && rotations.count(view_id) > 0;
}

std::vector<PositioningTrack> MakePositioningTracks(const SfmData& sfm_data, const FeaturesPerView& features,
                                                    const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                    const std::vector<Track>& tracks) {
  const std::map<IndexT, RayView> views = PositionableViews(sfm_data, features, rotations);
  std::vector<PositioningTrack> result;
  for (size_t track_id = 0; track_id < tracks.size(); ++track_id) {
    PositioningTrack track;
    track.track_id = track_id;
    for (const auto& [view_id, feature_id] : tracks[track_id]) {
      const auto view = views.find(view_id);
      if (view == views.end()) continue;
      PositioningObservation observation;
      observation.view_id = view_id;
      observation.feature_id = feature_id;
      observation.pixel = CheckedPosition(view->second, track_id, view_id, feature_id);
      observation.bearing = view->second.intrinsics->Unproject(observation.pixel).normalized();
      observation.ray_world = view->second.camera_to_world * observation.bearing;
      track.observations.push_back(observation);
    }
    if (track.observations.size() >= 2) result.push_back(std::move(track));
  }
  return result;
}

std::vector<SampledTrack> PositionableTrackPixels(const SfmData& sfm_data, const FeaturesPerView& features,
                                                  const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                  const std::vector<Track>& tracks) {
  const std::map<IndexT, RayView> views = PositionableViews(sfm_data, features, rotations);
  std::vector<SampledTrack> result(tracks.size());
  for (size_t track_id = 0; track_id < tracks.size(); ++track_id) {
    SampledTrack& sampled = result[track_id];
    for (const auto& [view_id, feature_id] : tracks[track_id]) {
      const auto view = views.find(view_id);
      if (view == views.end()) continue;
      sampled.push_back({view_id, CheckedPosition(view->second, track_id, view_id, feature_id)});
    }
    if (sampled.size() < 2) sampled.clear();
  }
  return result;
}

std::string CheckOnePosePerView(const SfmData& sfm_data, const std::map<IndexT, Eigen::Matrix3d>& rotations) {
  std::set<IndexT> pose_ids;
  for (const auto& [view_id, rotation] : rotations) {
    if (!CanReceivePose(sfm_data, rotations, view_id)) continue;
    const IndexT pose_id = sfm_data.views.at(view_id).id_pose;
    if (!pose_ids.insert(pose_id).second) {
      return "views share pose id " + std::to_string(pose_id) + " (rigs are not supported)";
    }
  }
  return {};
}

}  // namespace sfm_pruning
