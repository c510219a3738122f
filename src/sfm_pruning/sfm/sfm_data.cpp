#include "sfm_pruning/sfm/sfm_data.hpp"

#include <set>
#include <string>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

bool SfmData::IsPosed(const View& view) const {
  return poses.count(view.id_pose) != 0 && intrinsics.count(view.id_intrinsic) != 0;
}

const CameraIntrinsics* SfmData::FindIntrinsics(IndexT view_id) const {
  const auto view = views.find(view_id);
  if (view == views.end()) return nullptr;
  const auto it = intrinsics.find(view->second.id_intrinsic);
  return it == intrinsics.end() ? nullptr : &it->second;
}

bool SfmData::IsPosed(IndexT view_id) const {
  const auto it = views.find(view_id);
  return it != views.end() && IsPosed(it->second);
}

std::vector<IndexT> SfmData::PosedViewIds() const {
  std::vector<IndexT> ids;
  for (const auto& [id, view] : views) {
    if (IsPosed(view)) ids.push_back(id);
  }
  return ids;
}

bool SfmData::PosesEqual(const SfmData& o) const {
  if (poses.size() != o.poses.size()) return false;
  for (auto a = poses.begin(), b = o.poses.begin(); a != poses.end(); ++a, ++b) {
    if (a->first != b->first || a->second.rotation != b->second.rotation ||
        a->second.center != b->second.center) {
      return false;
    }
  }
  return true;
}

void ValidateSfmData(const SfmData& data, const std::string& source) {
  std::set<IndexT> used_intrinsics, used_poses;
  for (const auto& [key, view] : data.views) {
    if (view.id_view != key) {
      throw FileError(source, "view key " + std::to_string(key) + " holds id_view " +
                                  std::to_string(view.id_view));
    }
    used_intrinsics.insert(view.id_intrinsic);
    used_poses.insert(view.id_pose);
  }
  for (const auto& [id, intrinsic] : data.intrinsics) {
    if (!used_intrinsics.count(id)) {
      throw FileError(source, "intrinsic " + std::to_string(id) + " is used by no view");
    }
  }
  for (const auto& [id, pose] : data.poses) {
    if (!used_poses.count(id)) throw FileError(source, "pose " + std::to_string(id) + " is used by no view");
  }
  const auto check_observations = [&](const std::map<IndexT, Landmark>& landmarks, const char* what) {
    for (const auto& [id, landmark] : landmarks) {
      for (const auto& [view_id, observation] : landmark.observations) {
        if (!data.views.count(view_id)) {
          throw FileError(source, std::string(what) + " " + std::to_string(id) +
                                      " is observed in view " + std::to_string(view_id) +
                                      ", which does not exist");
        }
      }
    }
  };
  check_observations(data.structure, "landmark");
  check_observations(data.control_points, "control point");
}

}  // namespace sfm_pruning
