// The observations of the tracks as world-frame rays: the input of global positioning
// (GLOMAP's v_ik) and of the triangulation after translation averaging.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/global/track_subsampling.hpp"
#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct PositioningObservation {
  IndexT view_id = kUndefinedIndex;
  IndexT feature_id = kUndefinedIndex;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // raw (distorted) feature position
  Eigen::Vector3d bearing = Eigen::Vector3d::UnitZ();    // unit, camera frame (Unproject)
  Eigen::Vector3d ray_world = Eigen::Vector3d::UnitZ();  // unit, world frame: R_i^T bearing
};

struct PositioningTrack {
  size_t track_id = 0;  // index into the input track list
  std::vector<PositioningObservation> observations;  // view id order
};

// True when the view exists in sfm_data with a pose id and has a rotation: a pose can be written.
bool CanReceivePose(const SfmData& sfm_data, const std::map<IndexT, Eigen::Matrix3d>& rotations, IndexT view_id);

// The rays of the observations made by views that can receive a pose and have intrinsics and
// features; other observations are dropped, then tracks left with fewer than two observations.
// Throws Error when a track names a feature its view does not have.
std::vector<PositioningTrack> MakePositioningTracks(const SfmData& sfm_data, const FeaturesPerView& features,
                                                    const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                    const std::vector<Track>& tracks);

// The pixels of the observations MakePositioningTracks would keep, one entry per track of `tracks`
// (empty when fewer than two remain): what the subsampling needs, without a ray per observation.
std::vector<SampledTrack> PositionableTrackPixels(const SfmData& sfm_data, const FeaturesPerView& features,
                                                  const std::map<IndexT, Eigen::Matrix3d>& rotations,
                                                  const std::vector<Track>& tracks);

// Empty when every view with a rotation can receive its own pose; otherwise why not (several
// views sharing one pose id, i.e. a rig, which positioning does not model).
std::string CheckOnePosePerView(const SfmData& sfm_data, const std::map<IndexT, Eigen::Matrix3d>& rotations);

}  // namespace sfm_pruning
