#include "sfm_pruning/export/undistorted_model.hpp"

#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

SfmData UndistortModel(const SfmData& data, const UndistortOptions& options) {
  SfmData undistorted = data;
  for (auto& [id, intrinsics] : undistorted.intrinsics) intrinsics = UndistortedIntrinsics(intrinsics, options);
  for (auto& [landmark_id, landmark] : undistorted.structure) {
    for (auto& [view_id, observation] : landmark.observations) {
      const View& view = data.views.at(view_id);
      if (data.intrinsics.count(view.id_intrinsic) == 0) continue;
      observation.x = UndistortedPixel(data.IntrinsicsOf(view), undistorted.IntrinsicsOf(view), observation.x);
    }
  }
  return undistorted;
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

void WriteUndistortedImages(const SfmData& original, const SfmData& undistorted, const fs::path& image_root,
                            const fs::path& output_dir, const ImageWriteOptions& options,
                            const ProgressCallback& progress) {
  const std::vector<IndexT> views = original.PosedViewIds();
  // One map per intrinsic that needs resampling, computed before the parallel loop.
  std::map<IndexT, std::shared_ptr<const UndistortionMaps>> maps;
  for (const IndexT view_id : views) {
    const IndexT intrinsic_id = original.views.at(view_id).id_intrinsic;
    const CameraIntrinsics& from = original.intrinsics.at(intrinsic_id);
    const CameraIntrinsics& to = undistorted.intrinsics.at(intrinsic_id);
    if (maps.count(intrinsic_id) == 0 && !SameProjection(from, to)) {
      maps[intrinsic_id] = std::make_shared<const UndistortionMaps>(ComputeUndistortionMaps(from, to));
    }
  }
  ParallelFor(
      views.size(), options.num_threads,
      [&](size_t index) {
        const View& view = original.views.at(views[index]);
        const fs::path source = image_root / view.RelativeImagePath();
        const fs::path target = output_dir / view.RelativeImagePath();
        const auto map = maps.find(view.id_intrinsic);
        if (map == maps.end()) {
          CopyImage(source, target);
          return;
        }
        const cv::Mat image = ReadImageAsStored(source);
        const CameraIntrinsics& camera = original.intrinsics.at(view.id_intrinsic);
        if (image.cols != static_cast<int>(camera.width()) || image.rows != static_cast<int>(camera.height())) {
          throw FileError(source.string(), "image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                               " but its camera is " + std::to_string(camera.width()) + "x" +
                                               std::to_string(camera.height()));
        }
        WriteImage(target, UndistortImage(image, *map->second), options.jpeg_quality);
      },
      progress, "undistorting images");
}

}  // namespace sfm_pruning
