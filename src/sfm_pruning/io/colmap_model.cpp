#include "sfm_pruning/io/colmap_model.hpp"

#include <Eigen/Geometry>
#include <string>
#include <utility>

#include "sfm_pruning/io/colmap_camera.hpp"
#include "sfm_pruning/io/colmap_model_records.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
using namespace colmap_records;

namespace {

// COLMAP image names may contain folders ("left/0001.png"); ours split them into local_path
// and filename, and RelativeImagePath() joins them back.
void SetImageName(const std::string& name, View* view) {
  const size_t slash = name.find_last_of('/');
  if (slash == std::string::npos) {
    view->filename = name;
  } else {
    view->local_path = name.substr(0, slash);
    view->filename = name.substr(slash + 1);
  }
}

Pose PoseFromQvecTvec(const Eigen::Vector4d& qvec, const Eigen::Vector3d& tvec) {
  // Normalized because hand-written text models may not carry unit quaternions.
  const Eigen::Quaterniond q = Eigen::Quaterniond(qvec[0], qvec[1], qvec[2], qvec[3]).normalized();
  return Pose::FromRotationTranslation(q.toRotationMatrix(), tvec);
}

SfmData ToSfmData(const Model& model, const fs::path& dir, bool binary) {
  const std::string cameras_file = (dir / CamerasFile(binary)).string();
  const std::string images_file = (dir / ImagesFile(binary)).string();
  const std::string points_file = (dir / Points3DFile(binary)).string();
  SfmData data;
  for (const auto& [camera_id, camera] : model.cameras) {
    data.intrinsics[camera_id] = FromColmapCamera(camera, cameras_file);
    const std::string problem = IntrinsicsProblem(data.intrinsics[camera_id]);
    if (!problem.empty()) throw FileError(cameras_file, "camera " + std::to_string(camera_id) + ": " + problem);
  }
  for (const auto& [image_id, image] : model.images) {
    const std::string name = "image " + std::to_string(image_id);
    const auto intrinsic = data.intrinsics.find(image.camera_id);
    if (intrinsic == data.intrinsics.end()) {
      throw FileError(images_file, name + " refers to missing camera " + std::to_string(image.camera_id));
    }
    if (!image.qvec.allFinite() || !image.tvec.allFinite()) {
      throw FileError(images_file, name + ": its pose (QVEC, TVEC) is not finite");
    }
    if (image.qvec.norm() == 0.0) throw FileError(images_file, name + ": its QVEC is zero, not a rotation");
    for (size_t k = 0; k < image.points2d.size(); ++k) {
      const int64_t point3d_id = image.points2d[k].point3d_id;
      if (!image.points2d[k].xy.allFinite()) {
        throw FileError(images_file, name + ": point2D " + std::to_string(k) + " is not a finite pixel");
      }
      if (point3d_id != kNoPoint3D && (point3d_id < 0 || !model.points3d.count(static_cast<uint64_t>(point3d_id)))) {
        throw FileError(images_file, name + ": point2D " + std::to_string(k) + " names 3D point " +
                                         std::to_string(point3d_id) + ", which is not in " +
                                         (dir / Points3DFile(binary)).filename().string());
      }
    }
    View view;
    view.id_view = image_id;
    view.id_pose = image_id;
    view.id_intrinsic = image.camera_id;
    view.width = intrinsic->second.width();
    view.height = intrinsic->second.height();
    SetImageName(image.name, &view);
    data.views[image_id] = view;
    data.poses[image_id] = PoseFromQvecTvec(image.qvec, image.tvec);
  }
  for (const auto& [point_id, point] : model.points3d) {
    if (point_id >= kUndefinedIndex) {
      throw FileError(points_file,
                      "point3D id " + std::to_string(point_id) + " exceeds PruneSfM's 32-bit ids");
    }
    Landmark landmark;
    landmark.X = point.xyz;
    landmark.color = point.rgb;
    landmark.error = point.error;
    for (const auto& [image_id, point2d_idx] : point.track) {
      const auto image = model.images.find(image_id);
      if (image == model.images.end() || point2d_idx >= image->second.points2d.size()) {
        throw FileError(points_file, "point3D " + std::to_string(point_id) + " observes missing point2D " +
                                         std::to_string(point2d_idx) + " of image " +
                                         std::to_string(image_id));
      }
      // A track lists an image once; should it repeat one, the first observation is kept.
      landmark.observations.emplace(
          image_id, Observation{FromColmapPixel(image->second.points2d[point2d_idx].xy), point2d_idx});
    }
    data.structure[static_cast<IndexT>(point_id)] = std::move(landmark);
  }
  return data;
}

// Fills the points2D of every written image; returns, per (view, landmark), the point2D index.
std::map<std::pair<IndexT, IndexT>, uint32_t> FillPoints2D(const SfmData& data,
                                                           const FeaturesPerView* features,
                                                           const fs::path& dir, Model* model) {
  std::map<std::pair<IndexT, IndexT>, uint32_t> index_of;
  if (features != nullptr) {
    for (auto& [image_id, image] : model->images) {
      const auto found = features->find(image_id);
      if (found == features->end()) continue;
      for (size_t k = 0; k < found->second.size(); ++k) {
        image.points2d.push_back({ToColmapPixel(found->second.Position(k)), kNoPoint3D});
      }
    }
  }
  for (const auto& [landmark_id, landmark] : data.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      const auto image = model->images.find(view_id);
      if (image == model->images.end()) continue;  // unposed view: not in the model
      std::vector<Point2D>& points = image->second.points2d;
      uint32_t index = static_cast<uint32_t>(points.size());
      if (features != nullptr) {
        index = observation.id_feat;
        if (index >= points.size()) {
          throw FileError(dir.string(), "landmark " + std::to_string(landmark_id) + " observes feature " +
                                            std::to_string(index) + " of view " + std::to_string(view_id) +
                                            ", which has " + std::to_string(points.size()) + " features");
        }
        if (points[index].point3d_id != kNoPoint3D) {
          throw FileError(dir.string(), "feature " + std::to_string(index) + " of view " +
                                            std::to_string(view_id) + " is observed by two landmarks");
        }
        points[index] = {ToColmapPixel(observation.x), landmark_id};
      } else {
        points.push_back({ToColmapPixel(observation.x), landmark_id});
      }
      index_of[{view_id, landmark_id}] = index;
    }
  }
  return index_of;
}

Model FromSfmData(const SfmData& data, const FeaturesPerView* features, const fs::path& dir) {
  Model model;
  for (const auto& [intrinsic_id, intrinsics] : data.intrinsics) {
    try {
      model.cameras[intrinsic_id] = ToColmapCamera(intrinsics);
    } catch (const Error& e) {
      throw FileError(dir.string(), "intrinsic " + std::to_string(intrinsic_id) + ": " + e.what());
    }
  }
  for (const auto& [view_id, view] : data.views) {
    if (!data.IsPosed(view)) continue;
    const Pose& pose = data.PoseOf(view);
    const Eigen::Quaterniond q(pose.rotation);
    Image& image = model.images[view_id];
    image.qvec = {q.w(), q.x(), q.y(), q.z()};
    image.tvec = pose.translation();
    image.camera_id = view.id_intrinsic;
    image.name = view.RelativeImagePath();
  }
  const auto index_of = FillPoints2D(data, features, dir, &model);
  for (const auto& [landmark_id, landmark] : data.structure) {
    Point3D point;
    point.xyz = landmark.X;
    point.rgb = landmark.color;
    point.error = landmark.error;
    for (const auto& [view_id, observation] : landmark.observations) {
      const auto index = index_of.find({view_id, landmark_id});
      if (index != index_of.end()) point.track.emplace_back(view_id, index->second);
    }
    if (!point.track.empty()) model.points3d[landmark_id] = std::move(point);
  }
  return model;
}

}  // namespace

ColmapModelFormat DetectColmapModelFormat(const fs::path& dir) {
  if (fs::exists(dir / CamerasFile(true))) return ColmapModelFormat::kBinary;
  if (fs::exists(dir / CamerasFile(false))) return ColmapModelFormat::kText;
  if (!fs::is_directory(dir)) throw FileError(dir.string(), "COLMAP model folder not found");
  throw FileError(dir.string(), "not a COLMAP model folder (no cameras.bin or cameras.txt)");
}

SfmData ReadColmapModel(const fs::path& dir) {
  const bool binary = DetectColmapModelFormat(dir) == ColmapModelFormat::kBinary;
  const Model model = binary ? ReadBinaryModel(dir) : ReadTextModel(dir);
  return ToSfmData(model, dir, binary);
}

void WriteColmapModel(const SfmData& data, const fs::path& dir, ColmapModelFormat format,
                      const FeaturesPerView* features) {
  // Converted before the folder is touched, so bad input leaves any existing model intact.
  const Model model = FromSfmData(data, features, dir);
  WriteDirectoryAtomically(dir, OutputFolderKind::kColmapModel, [&](const fs::path& tmp) {
    if (format == ColmapModelFormat::kBinary) {
      WriteBinaryModel(model, tmp);
    } else {
      WriteTextModel(model, tmp);
    }
  });
}

}  // namespace sfm_pruning
