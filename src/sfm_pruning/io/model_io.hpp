// Reading and writing a reconstruction in any model format the project supports, chosen from
// the path. Commands that accept "a model" (evaluate, convert, ...) go through ReadModel and
// WriteModel so that every format works everywhere.
#pragma once

#include <filesystem>
#include <string>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

enum class ModelFormat {
  kColmapModel,        // a directory holding cameras.bin or cameras.txt (+ images, points3D)
  kSfmData,            // OpenMVG sfm_data: *.json or *.bin
  kGroundTruthCameras, // a benchmark gt_cameras.txt (any *.txt file)
  kPly,                // *.ply: points (and camera centres) only
  kOpenMvsScene,       // *.mvs: OpenMVS scene (undistorted pinhole cameras only)
};

// Human-readable name for messages ("COLMAP model", "sfm_data", "gt_cameras.txt").
std::string ModelFormatName(ModelFormat format);

// Decides the format from the path alone:
//   directory containing cameras.bin or cameras.txt -> kColmapModel
//   file *.json or *.bin                            -> kSfmData
//   file *.txt                                      -> kGroundTruthCameras
//   file *.ply                                      -> kPly
//   file *.mvs                                      -> kOpenMvsScene
// Throws Error naming the path when it does not exist or matches none of these.
ModelFormat DetectModelFormat(const std::filesystem::path& path);

// The format an output path asks for: *.json / *.bin -> sfm_data, *.ply -> PLY, *.txt ->
// gt_cameras.txt, *.mvs -> OpenMVS scene, anything else (no extension, an existing folder) -> a COLMAP model folder.
ModelFormat OutputModelFormat(const std::filesystem::path& path);

// Reads the model with the reader of its detected format. Throws Error (one line naming the
// file and the problem) on any bad input.
SfmData ReadModel(const std::filesystem::path& path);

struct ModelWriteOptions {
  bool colmap_text = false;  // COLMAP folders: .txt files instead of .bin

  // Both values are valid: there is nothing to refuse. Kept so that every options struct has one
  // (util/option_checks.hpp).
  void Check() const;
};

// Writes `data` in the format OutputModelFormat(path) selects, atomically. gt_cameras.txt needs
// undistorted pinhole cameras; PLY keeps only points and camera centres. An OpenMVS scene needs
// undistorted pinhole cameras and names its images root_path/<image path> (openmvs_conversion.hpp);
// reading one sets root_path to the scene's folder, against which OpenMVS resolves image names.
void WriteModel(const SfmData& data, const std::filesystem::path& path, const ModelWriteOptions& options = {});

}  // namespace sfm_pruning
