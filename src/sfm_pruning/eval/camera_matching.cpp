#include "sfm_pruning/eval/camera_matching.hpp"

#include <filesystem>
#include <map>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

// Poses of the posed views keyed by image basename.
std::map<std::string, Pose> PosesByBasename(const SfmData& data, const std::string& source) {
  std::map<std::string, Pose> poses;
  for (const auto& [id, view] : data.views) {
    if (!data.IsPosed(view)) continue;
    const std::string name = std::filesystem::path(view.filename).filename().string();
    if (!poses.emplace(name, data.PoseOf(view)).second) {
      throw FileError(source, "image name '" + name + "' belongs to two posed views; cannot match by name");
    }
  }
  return poses;
}

}  // namespace

size_t CameraMatching::NumRegistered() const {
  size_t count = 0;
  for (const MatchedCamera& camera : cameras) count += camera.estimate.has_value() ? 1 : 0;
  return count;
}

CameraMatching MatchCamerasByName(const SfmData& estimate, const SfmData& ground_truth,
                                  const std::string& estimate_source, const std::string& ground_truth_source) {
  const std::map<std::string, Pose> estimated = PosesByBasename(estimate, estimate_source);
  const std::map<std::string, Pose> truth = PosesByBasename(ground_truth, ground_truth_source);
  CameraMatching matching;
  matching.num_estimate_images = estimated.size();
  for (const auto& [name, pose] : truth) {
    MatchedCamera camera{name, pose, std::nullopt};
    const auto it = estimated.find(name);
    if (it != estimated.end()) camera.estimate = it->second;
    matching.cameras.push_back(camera);
  }
  matching.num_unmatched_estimate_images = estimated.size() - matching.NumRegistered();
  return matching;
}

}  // namespace sfm_pruning
