// `prunesfm init`: a folder of images -> an OpenMVG scene (views + intrinsics, no poses).
// Every image is decoded once (undecodable files are reported and skipped, never fatal); the
// focal length of each camera comes from the user (--focal), a K file, EXIF, or the default guess
// (focal_prior.hpp). Views are numbered 0..N-1 in file-name order.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/features/focal_prior.hpp"
#include "sfm_pruning/sfm/camera_models.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

enum class CameraGrouping {
  kPerBodyAndSize,  // one intrinsic per (camera body from EXIF, image size, focal): OpenMVG's grouping
  kPerImage,        // one intrinsic per view
};

struct ImageListingOptions {
  std::optional<double> focal_px;          // --focal: every camera, trusted
  std::optional<Eigen::Matrix3d> K;        // io/k_file.hpp: focal(s) and principal point, trusted
  FocalPriorOptions focal;                 // EXIF and default guess
  CameraGrouping grouping = CameraGrouping::kPerBodyAndSize;
  // The distortion model the intrinsics are created with (all coefficients zero). kPinholeRadialK1
  // is COLMAP's SIMPLE_RADIAL. With a K whose fx != fy the model is kPinholeFxFy.
  CameraModel camera_model = CameraModel::kPinholeRadialK1;
  int num_threads = 1;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct SkippedImage {
  std::string filename;  // relative to the image folder
  std::string reason;
};

struct CameraGroupInfo {
  std::string body;  // "make model" from EXIF, or ""
  FocalSource focal_source = FocalSource::kDefaultGuess;
  size_t num_views = 0;
};

struct ImageListing {
  SfmData scene;                               // root_path = the image folder
  std::vector<SkippedImage> skipped;           // file-name order
  std::map<IndexT, CameraGroupInfo> cameras;   // keyed by intrinsic id
};

// The image files of `dir` (not recursive), sorted by name: extensions jpg, jpeg, png, tif, tiff,
// bmp, pgm, ppm, webp, any case. Throws Error when `dir` is not a folder or holds no image.
std::vector<std::string> ListImageFiles(const std::filesystem::path& dir);

// Throws Error (naming the folder) when no image decodes. Progress stage: "reading images".
ImageListing ListImages(const std::filesystem::path& image_dir, const ImageListingOptions& options,
                        const ProgressCallback& progress = {});

}  // namespace sfm_pruning
