// SfmData: the whole scene description (OpenMVG's SfM_Data): views, intrinsics, poses,
// landmarks and control points. Ordered maps keep every traversal deterministic.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/landmark.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/sfm/view.hpp"

namespace sfm_pruning {

struct SfmData {
  std::string root_path;  // folder of the images
  std::map<IndexT, View> views;
  std::map<IndexT, CameraIntrinsics> intrinsics;
  std::map<IndexT, Pose> poses;  // keyed by pose id
  std::map<IndexT, Landmark> structure;
  std::map<IndexT, Landmark> control_points;

  // A view is posed when its pose id exists in `poses` and its intrinsic in `intrinsics`.
  bool IsPosed(IndexT view_id) const;
  bool IsPosed(const View& view) const;
  const Pose& PoseOf(const View& view) const { return poses.at(view.id_pose); }
  const CameraIntrinsics& IntrinsicsOf(const View& view) const { return intrinsics.at(view.id_intrinsic); }
  // The intrinsics of view `view_id`; nullptr for an unknown view or one without intrinsics.
  const CameraIntrinsics* FindIntrinsics(IndexT view_id) const;
  std::vector<IndexT> PosedViewIds() const;

  bool operator==(const SfmData& o) const {
    return root_path == o.root_path && views == o.views && intrinsics == o.intrinsics &&
           PosesEqual(o) && structure == o.structure && control_points == o.control_points;
  }

 private:
  bool PosesEqual(const SfmData& o) const;
};

// Checks that every reference resolves: view ids match their keys, observations name existing
// views, no intrinsic or pose is orphaned (OpenMVG refuses to load such files). Throws Error
// whose message starts with `source` (usually the file the data came from).
void ValidateSfmData(const SfmData& data, const std::string& source);

}  // namespace sfm_pruning
