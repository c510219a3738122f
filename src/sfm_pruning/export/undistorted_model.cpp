#include "sfm_pruning/export/undistorted_model.hpp"

#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
namespace {

// One past the largest key of an id map (0 when empty).
template <typename Map>
IndexT NextFreeId(const Map& map) {
  return map.empty() ? 0 : map.rbegin()->first + 1;
}

std::string FaceFilename(const std::string& filename, int face) {
  const fs::path name(filename);
  return name.stem().string() + "_" + CubeFaceNames()[face] + name.extension().string();
}

// Replaces every posed spherical view of `model` by its six cube faces (see UndistortModel).
void SplitSphericalViews(const SfmData& original, UndistortedModel* model) {
  SfmData& data = model->data;
  IndexT next_view = NextFreeId(original.views);
  IndexT next_pose = NextFreeId(original.poses);
  for (const auto& [view_id, view] : original.views) {
    if (original.intrinsics.count(view.id_intrinsic) == 0 ||
        original.intrinsics.at(view.id_intrinsic).model() != CameraModel::kSpherical) {
      continue;
    }
    data.views.erase(view_id);
    model->sources.erase(view_id);
    if (!original.IsPosed(view)) {
      for (auto& [landmark_id, landmark] : data.structure) landmark.observations.erase(view_id);
      continue;
    }
    const Pose& pose = original.PoseOf(view);
    std::array<IndexT, kNumCubeFaces> face_views;
    for (int face = 0; face < kNumCubeFaces; ++face) {
      View face_view = view;
      face_view.id_view = face_views[face] = next_view++;
      face_view.id_pose = next_pose++;
      face_view.filename = FaceFilename(view.filename, face);
      face_view.width = face_view.height = data.intrinsics.at(view.id_intrinsic).width();
      face_view.center_prior.reset();
      face_view.has_prior_record = false;
      data.views[face_view.id_view] = face_view;
      const Eigen::Matrix3d& rotation = CubeFaceRotations()[face];
      data.poses[face_view.id_pose] = Pose(rotation * pose.rotation, pose.center);
      model->sources[face_view.id_view] = {view_id, face, rotation};
    }
    // Poses of the spherical view stay only if another view still uses them.
    bool pose_shared = false;
    for (const auto& [id, other] : data.views) pose_shared = pose_shared || other.id_pose == view.id_pose;
    if (!pose_shared) data.poses.erase(view.id_pose);
    // Observations move to the face their ray falls in.
    const CameraIntrinsics& sphere = original.intrinsics.at(view.id_intrinsic);
    const CameraIntrinsics& face_camera = data.intrinsics.at(view.id_intrinsic);
    for (auto& [landmark_id, landmark] : data.structure) {
      const auto observation = landmark.observations.find(view_id);
      if (observation == landmark.observations.end()) continue;
      const Eigen::Vector3d bearing = sphere.Unproject(observation->second.x);
      const int face = CubeFaceOf(bearing);
      Observation moved = observation->second;
      moved.x = face_camera.Project(CubeFaceRotations()[face] * bearing);
      landmark.observations.erase(observation);
      landmark.observations[face_views[face]] = moved;
    }
  }
}

}  // namespace

UndistortedModel UndistortModel(const SfmData& data, const UndistortOptions& options) {
  options.Check();
  UndistortedModel model;
  model.data = data;
  for (auto& [id, intrinsics] : model.data.intrinsics)
    intrinsics = UndistortedIntrinsics(intrinsics, options);
  for (const auto& [view_id, view] : data.views)
    model.sources[view_id] = {view_id, -1, Eigen::Matrix3d::Identity()};
  for (auto& [landmark_id, landmark] : model.data.structure) {
    for (auto& [view_id, observation] : landmark.observations) {
      const View& view = data.views.at(view_id);
      if (data.intrinsics.count(view.id_intrinsic) == 0 || !IsPinholeFamily(data.IntrinsicsOf(view).model()))
        continue;
      observation.x = UndistortedPixel(data.IntrinsicsOf(view), model.data.IntrinsicsOf(view), observation.x);
    }
  }
  SplitSphericalViews(data, &model);
  return model;
}

namespace {

void CopyImage(const fs::path& from, const fs::path& to) {
  std::error_code error;
  if (!fs::is_regular_file(from, error)) throw FileError(from.string(), "no such image file");
  fs::create_directories(to.parent_path(), error);
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
  if (error) throw FileError(to.string(), "cannot copy the image: " + error.message());
}

}  // namespace

void WriteUndistortedImages(const SfmData& original, const UndistortedModel& undistorted,
                            const fs::path& image_root, const fs::path& output_dir,
                            const ImageWriteOptions& options, const ProgressCallback& progress) {
  options.Check();
  const std::vector<IndexT> views = undistorted.data.PosedViewIds();
  // One map per (intrinsic, cube face) that needs resampling, computed before the parallel loop.
  using MapKey = std::pair<IndexT, int>;
  std::map<MapKey, std::shared_ptr<const UndistortionMaps>> maps;
  for (const IndexT view_id : views) {
    const UndistortedViewSource& source = undistorted.sources.at(view_id);
    const IndexT intrinsic_id = original.views.at(source.view).id_intrinsic;
    const CameraIntrinsics& from = original.intrinsics.at(intrinsic_id);
    const CameraIntrinsics& to = undistorted.data.intrinsics.at(intrinsic_id);
    const MapKey key{intrinsic_id, source.cube_face};
    if (maps.count(key) == 0 && (source.cube_face >= 0 || !SameProjection(from, to))) {
      maps[key] =
          std::make_shared<const UndistortionMaps>(ComputeUndistortionMaps(from, to, source.rotation));
    }
  }
  ParallelFor(
      views.size(), options.num_threads,
      [&](size_t index) {
        const UndistortedViewSource& source = undistorted.sources.at(views[index]);
        const View& view = original.views.at(source.view);
        const fs::path from = image_root / view.RelativeImagePath();
        const fs::path to = output_dir / undistorted.data.views.at(views[index]).RelativeImagePath();
        const auto map = maps.find({view.id_intrinsic, source.cube_face});
        if (map == maps.end()) {
          CopyImage(from, to);
          return;
        }
        const cv::Mat image = ReadImageAsStored(from);
        const CameraIntrinsics& camera = original.intrinsics.at(view.id_intrinsic);
        if (image.cols != static_cast<int>(camera.width()) ||
            image.rows != static_cast<int>(camera.height())) {
          throw FileError(from.string(), "image is " + std::to_string(image.cols) + "x" +
                                             std::to_string(image.rows) + " but its camera is " +
                                             std::to_string(camera.width()) + "x" +
                                             std::to_string(camera.height()));
        }
        WriteImage(to, UndistortImage(image, *map->second), options.jpeg_quality);
      },
      progress, "undistorting images");
}

void ImageWriteOptions::Check() const {
  RequireAtLeast(num_threads, 1, "ImageWriteOptions::num_threads");
  // OpenCV's IMWRITE_JPEG_QUALITY range.
  RequireInRange(jpeg_quality, 0, 100, "ImageWriteOptions::jpeg_quality");
}

}  // namespace sfm_pruning
