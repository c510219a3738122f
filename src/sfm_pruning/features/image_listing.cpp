#include "sfm_pruning/features/image_listing.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>

#include "sfm_pruning/features/image_decoding.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
namespace {

const std::set<std::string> kImageExtensions = {".jpg", ".jpeg", ".png", ".tif", ".tiff",
                                                ".bmp", ".pgm",  ".ppm", ".webp"};

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// What one image contributes before grouping.
struct ImageProbe {
  bool decoded = false;
  std::string problem;
  uint32_t width = 0;
  uint32_t height = 0;
  std::string body;
  FocalPrior focal;
};

FocalPrior ChooseFocal(const ImageListingOptions& options, const std::optional<ExifMetadata>& exif, uint32_t width,
                       uint32_t height) {
  if (options.focal_px) return {*options.focal_px, FocalSource::kUserFocal};
  if (options.K) return {0.5 * ((*options.K)(0, 0) + (*options.K)(1, 1)), FocalSource::kKFile};
  return FocalFromExif(exif ? &*exif : nullptr, width, height, options.focal);
}

CameraIntrinsics MakeIntrinsics(const ImageListingOptions& options, const ImageProbe& probe) {
  if (options.K) {
    const Eigen::Matrix3d& K = *options.K;
    if (K(0, 0) != K(1, 1)) {
      return CameraIntrinsics(CameraModel::kPinholeFxFy, probe.width, probe.height, {K(0, 0), K(1, 1), K(0, 2), K(1, 2)});
    }
    return CameraIntrinsics::Undistorted(options.camera_model, probe.width, probe.height, K(0, 0), K(0, 2), K(1, 2));
  }
  // Principal point at the image centre, in the convention where pixel (0, 0) is a pixel centre.
  return CameraIntrinsics::Undistorted(options.camera_model, probe.width, probe.height, probe.focal.focal_px,
                                       0.5 * (probe.width - 1.0), 0.5 * (probe.height - 1.0));
}

}  // namespace

std::vector<std::string> ListImageFiles(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw FileError(dir.string(), "not a folder of images");
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    if (kImageExtensions.count(Lower(entry.path().extension().string())) > 0) {
      files.push_back(entry.path().filename().string());
    }
  }
  if (ec) throw FileError(dir.string(), "cannot list the folder: " + ec.message());
  if (files.empty()) throw FileError(dir.string(), "no image files (jpg, jpeg, png, tif, tiff, bmp, pgm, ppm, webp)");
  std::sort(files.begin(), files.end());
  return files;
}

ImageListing ListImages(const fs::path& image_dir, const ImageListingOptions& options,
                        const ProgressCallback& progress) {
  options.Check();
  const std::vector<std::string> files = ListImageFiles(image_dir);
  std::vector<ImageProbe> probes(files.size());
  ParallelFor(
      files.size(), options.num_threads,
      [&](size_t k) {
        ImageProbe& probe = probes[k];
        const fs::path path = image_dir / files[k];
        const DecodedImage image = DecodeGrayImage(path);
        if (!image.ok()) {
          probe.problem = image.problem;
          return;
        }
        probe.decoded = true;
        probe.width = static_cast<uint32_t>(image.pixels.cols);
        probe.height = static_cast<uint32_t>(image.pixels.rows);
        const std::optional<ExifMetadata> exif = ReadExifMetadata(path);
        if (exif) probe.body = exif->Body();
        probe.focal = ChooseFocal(options, exif, probe.width, probe.height);
      },
      progress, "reading images");

  ImageListing listing;
  listing.scene.root_path = fs::absolute(image_dir).lexically_normal().string();
  // Intrinsic groups in order of first appearance; the focal is part of the key so that a zoom
  // lens at two focal lengths gives two cameras.
  std::map<std::tuple<std::string, uint32_t, uint32_t, double>, IndexT> groups;
  for (size_t k = 0; k < files.size(); ++k) {
    const ImageProbe& probe = probes[k];
    if (!probe.decoded) {
      listing.skipped.push_back({files[k], probe.problem});
      continue;
    }
    const IndexT view_id = static_cast<IndexT>(listing.scene.views.size());
    IndexT intrinsic_id = static_cast<IndexT>(listing.scene.intrinsics.size());
    if (options.grouping == CameraGrouping::kPerBodyAndSize) {
      const auto key = std::make_tuple(probe.body, probe.width, probe.height, probe.focal.focal_px);
      intrinsic_id = groups.emplace(key, intrinsic_id).first->second;
    }
    if (listing.scene.intrinsics.count(intrinsic_id) == 0) {
      listing.scene.intrinsics.emplace(intrinsic_id, MakeIntrinsics(options, probe));
      listing.cameras[intrinsic_id] = {probe.body, probe.focal.source, 0};
    }
    ++listing.cameras[intrinsic_id].num_views;
    View view;
    view.id_view = view_id;
    view.id_pose = view_id;
    view.id_intrinsic = intrinsic_id;
    view.filename = files[k];
    view.width = probe.width;
    view.height = probe.height;
    listing.scene.views.emplace(view_id, view);
  }
  if (listing.scene.views.empty()) {
    throw FileError(image_dir.string(), "none of the " + std::to_string(files.size()) + " images decodes (first: " +
                                            listing.skipped.front().filename + ": " +
                                            listing.skipped.front().reason + ")");
  }
  return listing;
}

void ImageListingOptions::Check() const {
  if (focal_px) RequirePositiveFinite(*focal_px, "ImageListingOptions::focal_px");
  // What ReadKFile (io/k_file.hpp) accepts: the intrinsics take fx, fy, cx and cy from it.
  if (K) {
    const Eigen::Matrix3d& k = *K;
    const bool camera_matrix = k(0, 0) > 0.0 && k(1, 1) > 0.0 && k(1, 0) == 0.0 && k(2, 0) == 0.0 &&
                               k(2, 1) == 0.0 && k(2, 2) == 1.0 && std::isfinite(k.sum());
    if (!camera_matrix) {
      throw std::invalid_argument(
          "ImageListingOptions::K must be a finite camera matrix [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0");
    }
  }
  focal.Check();
  RequireAtLeast(num_threads, 1, "ImageListingOptions::num_threads");
}

}  // namespace sfm_pruning
