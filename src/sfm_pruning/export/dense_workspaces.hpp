// Workspaces for dense reconstruction: undistorted images plus the model in the layout each tool
// reads. Each output folder is written atomically (a temporary sibling renamed into place).
#pragma once

#include <cstdint>
#include <filesystem>

#include "sfm_pruning/export/undistorted_model.hpp"
#include "sfm_pruning/export/undistortion.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

struct DenseWorkspaceOptions {
  UndistortOptions undistort;
  ImageWriteOptions images;
  uint32_t openmvs_version = kOpenMvsExportVersion;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// COLMAP's undistorted workspace, what `colmap image_undistorter` writes and what COLMAP's dense
// pipeline, Gaussian splatting and NeRF tools read:
//   images/<image path>           undistorted images of the posed views
//   sparse/cameras.bin ...        the undistorted model, PINHOLE cameras
//   stereo/patch-match.cfg        every image with "__auto__, 20" (COLMAP picks 20 source images)
//   stereo/fusion.cfg             every image
//   stereo/depth_maps, normal_maps, consistency_graphs   empty, filled by patch_match_stereo
//   run-colmap-geometric.sh       the dense commands, for reference
void WriteColmapUndistortedWorkspace(const SfmData& data, const std::filesystem::path& image_root,
                                     const std::filesystem::path& output_dir,
                                     const DenseWorkspaceOptions& options = {},
                                     const ProgressCallback& progress = {});

// An OpenMVS workspace: output_dir/scene.mvs naming images/<image path> (relative to the scene
// file, as OpenMVS resolves them) and the undistorted images there. Landmark colours become the
// vertex colours.
void WriteOpenMvsWorkspace(const SfmData& data, const std::filesystem::path& image_root,
                           const std::filesystem::path& output_dir, const DenseWorkspaceOptions& options = {},
                           const ProgressCallback& progress = {});

}  // namespace sfm_pruning
