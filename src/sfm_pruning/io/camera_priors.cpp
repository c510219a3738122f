#include "sfm_pruning/io/camera_priors.hpp"

#include <nlohmann/json.hpp>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

std::set<IndexT> CameraPriors::IntrinsicsWithGuessedFocal() const {
  std::set<IndexT> ids;
  for (const CameraPrior& camera : cameras) {
    if (!camera.focal_trusted) ids.insert(camera.intrinsic_id);
  }
  return ids;
}

std::set<IndexT> CameraPriors::IntrinsicsFromKFile() const {
  std::set<IndexT> ids;
  for (const CameraPrior& camera : cameras) {
    if (camera.focal_source == "k_file") ids.insert(camera.intrinsic_id);  // FocalSourceName(kKFile)
  }
  return ids;
}

void WriteCameraPriors(const std::filesystem::path& path, const CameraPriors& priors) {
  nlohmann::json cameras = nlohmann::json::array();
  for (const CameraPrior& c : priors.cameras) {
    cameras.push_back({{"intrinsic_id", c.intrinsic_id},
                       {"body", c.body},
                       {"focal_px", c.focal_px},
                       {"focal_source", c.focal_source},
                       {"focal_trusted", c.focal_trusted},
                       {"num_views", c.num_views}});
  }
  nlohmann::json skipped = nlohmann::json::array();
  for (const SkippedImageRecord& s : priors.skipped_images) skipped.push_back({{"image", s.image}, {"reason", s.reason}});
  const nlohmann::json json = {{"cameras", std::move(cameras)}, {"skipped_images", std::move(skipped)}};
  WriteFileAtomically(path, false, [&](std::ostream& out) { out << json.dump(2) << "\n"; });
}

CameraPriors ReadCameraPriors(const std::filesystem::path& path) {
  CameraPriors priors;
  try {
    const nlohmann::json json = nlohmann::json::parse(ReadFileToString(path, false));
    for (const nlohmann::json& c : json.at("cameras")) {
      CameraPrior camera;
      camera.intrinsic_id = c.at("intrinsic_id").get<IndexT>();
      camera.body = c.at("body").get<std::string>();
      camera.focal_px = c.at("focal_px").get<double>();
      camera.focal_source = c.at("focal_source").get<std::string>();
      camera.focal_trusted = c.at("focal_trusted").get<bool>();
      camera.num_views = c.at("num_views").get<size_t>();
      priors.cameras.push_back(std::move(camera));
    }
    for (const nlohmann::json& s : json.at("skipped_images")) {
      priors.skipped_images.push_back({s.at("image").get<std::string>(), s.at("reason").get<std::string>()});
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(path.string(), std::string("not a camera_priors.json: ") + e.what());
  }
  return priors;
}

}  // namespace sfm_pruning
