// camera_priors.json, written by `prunesfm init` beside its sfm_data.json: where each camera's
// initial focal length came from and whether it is trusted (a guess is not: COLMAP's
// prior_focal_length = 0), plus the images that were skipped because they do not decode.
// sfm_data.json itself has no room for this (OpenMVG's format stores the focal only).
//
//   {"cameras": [{"intrinsic_id": 0, "body": "Canon EOS 5D", "focal_px": 2759.5,
//                 "focal_source": "exif_35mm", "focal_trusted": true, "num_views": 11}, ...],
//    "skipped_images": [{"image": "broken.jpg", "reason": "does not decode as an image"}, ...]}
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct CameraPrior {
  IndexT intrinsic_id = kUndefinedIndex;
  std::string body;          // "make model" from EXIF, or ""
  double focal_px = 0.0;
  std::string focal_source;  // features/focal_prior.hpp FocalSourceName
  bool focal_trusted = false;
  size_t num_views = 0;
};

struct SkippedImageRecord {
  std::string image;
  std::string reason;
};

struct CameraPriors {
  std::vector<CameraPrior> cameras;  // intrinsic id order
  std::vector<SkippedImageRecord> skipped_images;

  // Intrinsic ids whose focal is a guess (the calibration's input).
  std::set<IndexT> IntrinsicsWithGuessedFocal() const;
  // Intrinsic ids whose whole K came from a calibration file (focal_source "k_file").
  std::set<IndexT> IntrinsicsFromKFile() const;
};

inline constexpr char kCameraPriorsFileName[] = "camera_priors.json";

// Atomic.
void WriteCameraPriors(const std::filesystem::path& path, const CameraPriors& priors);
// Throws Error naming the file when it is missing, not JSON or lacks a field.
CameraPriors ReadCameraPriors(const std::filesystem::path& path);

}  // namespace sfm_pruning
