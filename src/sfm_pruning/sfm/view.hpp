// A view: one image of the scene, as in OpenMVG's sfm_data.json.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

// A GPS-like prior on the camera centre (OpenMVG's "view_priors" subtype of View).
struct PoseCenterPrior {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d weight = Eigen::Vector3d::Ones();
  bool operator==(const PoseCenterPrior& o) const { return center == o.center && weight == o.weight; }
};

struct View {
  IndexT id_view = kUndefinedIndex;
  IndexT id_intrinsic = kUndefinedIndex;  // kUndefinedIndex: calibration unknown
  IndexT id_pose = kUndefinedIndex;       // may be shared by several views (rigs)
  std::string local_path;                 // folder below SfmData::root_path, usually ""
  std::string filename;                   // image file name
  uint32_t width = 0;
  uint32_t height = 0;
  // Present for OpenMVG "view_priors" views. `has_prior_record` marks a view_priors view whose
  // prior is disabled, so the type survives a round trip.
  std::optional<PoseCenterPrior> center_prior;
  bool has_prior_record = false;

  // Path of the image relative to the root path: local_path/filename.
  std::string RelativeImagePath() const {
    if (local_path.empty()) return filename;
    return local_path.back() == '/' ? local_path + filename : local_path + "/" + filename;
  }

  bool operator==(const View& o) const {
    return id_view == o.id_view && id_intrinsic == o.id_intrinsic && id_pose == o.id_pose &&
           local_path == o.local_path && filename == o.filename && width == o.width &&
           height == o.height && center_prior == o.center_prior && has_prior_record == o.has_prior_record;
  }
};

}  // namespace sfm_pruning
