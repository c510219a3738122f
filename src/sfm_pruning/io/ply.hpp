// PLY export of a reconstruction: landmarks (coloured) and, optionally, camera centres (green),
// the way OpenMVG's cloud_and_poses.ply and COLMAP's points3D.ply are commonly viewed.
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct PlyWriteOptions {
  bool binary = true;            // binary_little_endian; ASCII when false
  bool include_cameras = true;   // camera centres as extra green vertices
  bool include_control_points = false;

  // Every combination is valid: there is nothing to refuse. Kept so that every options struct
  // has one (util/option_checks.hpp).
  void Check() const;
};

// Writes vertices x y z (double) + red green blue (uchar). Atomic.
void WritePly(const SfmData& data, const std::filesystem::path& path, const PlyWriteOptions& options = {});

// Reads the vertices of a PLY written by WritePly (or any PLY whose vertex element starts with
// x y z, ASCII or binary little endian) as landmarks without observations.
SfmData ReadPlyPoints(const std::filesystem::path& path);

}  // namespace sfm_pruning
