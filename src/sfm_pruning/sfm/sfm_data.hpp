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

// Checks that every reference resolves: view ids match their keys, a view's intrinsic (unless
// undefined) exists, observations name existing views, no intrinsic or pose is orphaned (OpenMVG
// refuses to load such files); then the values (ValidateSfmDataValues). Throws Error whose
// message starts with `source` (usually the file the data came from). `intrinsics_loaded` false:
// only the views of a file were read, so their intrinsic ids are not looked up.
void ValidateSfmData(const SfmData& data, const std::string& source, bool intrinsics_loaded = true);

// Checks the numbers: every intrinsic passes IntrinsicsProblem, every pose has a finite centre
// within ±1e12 and a proper rotation, every landmark is finite and within ±1e12, every
// observation finite and within ±1e9 px. A NaN focal or a rotation of
// NaNs would otherwise run the solvers for minutes and end in a NaN model.
void ValidateSfmDataValues(const SfmData& data, const std::string& source);

// Why `intrinsics` cannot describe a real camera (empty when it can): an empty or absurd image
// size, a parameter that is not finite, a focal length that is not positive or is more than a
// thousand image sides (a field of view under 0.06 degrees: a unit mistake, not a lens), a
// principal point more than a thousand image sides from the image centre.
std::string IntrinsicsProblem(const CameraIntrinsics& intrinsics);

}  // namespace sfm_pruning
