#include "sfm_pruning/export/dense_workspaces.hpp"

#include <ostream>
#include <string>
#include <system_error>

#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
namespace {

void CreateFolder(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw FileError(dir.string(), "cannot create directory: " + error.message());
}

// The two configuration files COLMAP's patch_match_stereo and stereo_fusion read in a COLMAP
// workspace: patch-match.cfg pairs every reference image with its source images ("__auto__, N":
// the N images sharing most points), fusion.cfg lists the images to fuse.
void WriteStereoFolder(const SfmData& undistorted, const fs::path& stereo) {
  for (const char* sub : {"depth_maps", "normal_maps", "consistency_graphs"}) CreateFolder(stereo / sub);
  const auto names = undistorted.PosedViewIds();
  WriteFileAtomically(stereo / "patch-match.cfg", false, [&](std::ostream& out) {
    for (const IndexT id : names) out << undistorted.views.at(id).RelativeImagePath() << "\n__auto__, 20\n";
  });
  WriteFileAtomically(stereo / "fusion.cfg", false, [&](std::ostream& out) {
    for (const IndexT id : names) out << undistorted.views.at(id).RelativeImagePath() << "\n";
  });
}

void WriteDenseScript(const fs::path& path) {
  WriteFileAtomically(path, false, [](std::ostream& out) {
    out << "#!/bin/sh\n"
           "# Dense reconstruction of this workspace with COLMAP (written by prunesfm export).\n"
           "# Run from this folder; patch_match_stereo needs COLMAP built with CUDA.\n"
           "set -e\n"
           "colmap patch_match_stereo --workspace_path . --workspace_format COLMAP \\\n"
           "  --PatchMatchStereo.geom_consistency true\n"
           "colmap stereo_fusion --workspace_path . --workspace_format COLMAP \\\n"
           "  --input_type geometric --output_path fused.ply\n";
  });
  std::error_code ignored;
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add, ignored);
}

// Gaussian-splatting and NeRF tools open SOURCE/sparse/0/*.bin, COLMAP's dense tools
// WORKSPACE/sparse/*.bin: the model is in both places, the second as hard links to the first
// (no extra space; a copy where the file system has no hard links).
void LinkModelIntoSubfolderZero(const fs::path& sparse) {
  const fs::path zero = sparse / "0";
  fs::create_directories(zero);
  for (const char* name : {"cameras.bin", "images.bin", "points3D.bin"}) {
    std::error_code error;
    fs::create_hard_link(sparse / name, zero / name, error);
    if (error) fs::copy_file(sparse / name, zero / name, fs::copy_options::overwrite_existing);
  }
}

}  // namespace

void WriteColmapUndistortedWorkspace(const SfmData& data, const fs::path& image_root,
                                     const fs::path& output_dir, const DenseWorkspaceOptions& options,
                                     const ProgressCallback& progress) {
  options.Check();
  const UndistortedModel undistorted = UndistortModel(data, options.undistort);
  WriteDirectoryAtomically(output_dir, OutputFolderKind::kColmapDenseWorkspace, [&](const fs::path& dir) {
    WriteUndistortedImages(data, undistorted, image_root, dir / "images", options.images, progress);
    WriteColmapModel(undistorted.data, dir / "sparse", ColmapModelFormat::kBinary);
    LinkModelIntoSubfolderZero(dir / "sparse");
    WriteStereoFolder(undistorted.data, dir / "stereo");
    WriteDenseScript(dir / "run-colmap-geometric.sh");
  });
}

void WriteOpenMvsWorkspace(const SfmData& data, const fs::path& image_root, const fs::path& output_dir,
                           const DenseWorkspaceOptions& options, const ProgressCallback& progress) {
  options.Check();
  const UndistortedModel undistorted = UndistortModel(data, options.undistort);
  const OpenMvsScene scene = OpenMvsSceneFromSfmData(undistorted.data, "images", options.openmvs_version);
  WriteDirectoryAtomically(output_dir, OutputFolderKind::kOpenMvsWorkspace, [&](const fs::path& dir) {
    WriteUndistortedImages(data, undistorted, image_root, dir / "images", options.images, progress);
    WriteOpenMvsScene(scene, dir / "scene.mvs");
  });
}

void DenseWorkspaceOptions::Check() const {
  undistort.Check();
  images.Check();
  // WriteOpenMvsScene refuses newer versions, but only after every image is undistorted.
  RequireInRange(openmvs_version, 0u, kOpenMvsNewestVersion, "DenseWorkspaceOptions::openmvs_version");
}

}  // namespace sfm_pruning
