// Reading a reconstruction from any model format the project reads, chosen from the path.
// Commands that accept "a model" (evaluate, convert, ...) go through ReadModel so that every
// format works everywhere.
#pragma once

#include <filesystem>
#include <string>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

enum class ModelFormat {
  kColmapModel,        // a directory holding cameras.bin or cameras.txt (+ images, points3D)
  kSfmData,            // OpenMVG sfm_data: *.json or *.bin
  kGroundTruthCameras, // a benchmark gt_cameras.txt (any *.txt file)
};

// Human-readable name for messages ("COLMAP model", "sfm_data", "gt_cameras.txt").
std::string ModelFormatName(ModelFormat format);

// Decides the format from the path alone:
//   directory containing cameras.bin or cameras.txt -> kColmapModel
//   file *.json or *.bin                            -> kSfmData
//   file *.txt                                      -> kGroundTruthCameras
// Throws Error naming the path when it does not exist or matches none of these.
ModelFormat DetectModelFormat(const std::filesystem::path& path);

// Reads the model with the reader of its detected format. Throws Error (one line naming the
// file and the problem) on any bad input.
SfmData ReadModel(const std::filesystem::path& path);

}  // namespace sfm_pruning
