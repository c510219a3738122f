// prunesfm export: a reconstruction out to the tools that come after SfM. Dense workspaces
// (OpenMVS, COLMAP undistorted) carry undistorted images and pinhole cameras; the point formats
// carry colours sampled from the images (docs/export.md).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "sfm_pruning/export/dense_workspaces.hpp"
#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;
using sfm_pruning::Error;

struct ExportArguments {
  std::string model;
  std::string images;
  std::string format;
  std::string output;
  std::string output_type = "BIN";
  bool keep_all_pixels = false;
  int jpeg_quality = 95;
  int num_threads = 1;
  bool overwrite = false;
};

// The formats that need the images: those that write undistorted images. The others colour the
// points from the images when they are given and keep the model's colours otherwise.
bool NeedsImages(const std::string& format) { return format == "openmvs" || format == "colmap-undistorted"; }

void RequireExtension(const ExportArguments& args, std::initializer_list<const char*> extensions) {
  const std::string extension = fs::path(args.output).extension().string();
  std::string list;
  for (const char* allowed : extensions) {
    if (extension == allowed) return;
    list += std::string(list.empty() ? "" : " or ") + allowed;
  }
  throw Error(args.output + ": --format " + args.format + " writes a file ending in " + list);
}

// The kind of folder a format writes; none for the formats that write one file.
std::optional<sfm_pruning::OutputFolderKind> FolderKind(const std::string& format) {
  using sfm_pruning::OutputFolderKind;
  if (format == "openmvs") return OutputFolderKind::kOpenMvsWorkspace;
  if (format == "colmap-undistorted") return OutputFolderKind::kColmapDenseWorkspace;
  if (format == "colmap") return OutputFolderKind::kColmapModel;
  return std::nullopt;
}

void RunExport(const ExportArguments& args) {
  RefuseOutputOverInput(args.output, {args.model, args.images});
  if (const auto kind = FolderKind(args.format)) sfm_pruning::CheckOutputFolder(args.output, *kind, args.overwrite);
  sfm_pruning::SfmData data = sfm_pruning::ReadModel(args.model);
  const std::string image_root = args.images.empty() ? data.root_path : args.images;
  RefuseOutputOverInput(args.output, {image_root});
  if (image_root.empty() && NeedsImages(args.format)) {
    throw Error(args.model + ": --format " + args.format +
                " needs the images; give --images (the model names no image folder)");
  }
  if (!image_root.empty() && !fs::is_directory(image_root))
    throw Error(image_root + ": image folder does not exist");
  if (args.format == "ply") RequireExtension(args, {".ply"});
  if (args.format == "json") RequireExtension(args, {".json", ".bin"});
  const sfm_pruning::ProgressCallback progress = ProgressOnStderr();
  if (!image_root.empty()) {
    sfm_pruning::ColorLandmarksFromImages(&data, image_root, args.num_threads, progress);
    data.root_path = image_root;
  }
  sfm_pruning::DenseWorkspaceOptions options;
  options.undistort.fit = args.keep_all_pixels ? sfm_pruning::UndistortFit::kKeepAllPixels
                                               : sfm_pruning::UndistortFit::kNoBlackBorders;
  options.images.num_threads = args.num_threads;
  options.images.jpeg_quality = args.jpeg_quality;
  if (args.format == "openmvs") {
    sfm_pruning::WriteOpenMvsWorkspace(data, image_root, args.output, options, progress);
  } else if (args.format == "colmap-undistorted") {
    sfm_pruning::WriteColmapUndistortedWorkspace(data, image_root, args.output, options, progress);
  } else if (args.format == "colmap") {
    sfm_pruning::WriteColmapModel(data, args.output,
                                  args.output_type == "TXT" ? sfm_pruning::ColmapModelFormat::kText
                                                            : sfm_pruning::ColmapModelFormat::kBinary);
  } else if (args.format == "ply") {
    sfm_pruning::PlyWriteOptions ply;
    ply.include_cameras = false;
    sfm_pruning::WritePly(data, args.output, ply);
  } else {
    sfm_pruning::WriteSfmData(data, args.output);
  }
  Info("exported " + args.format + " to " + args.output + " (" + std::to_string(data.PosedViewIds().size()) +
       " posed views, " + std::to_string(data.structure.size()) + " points" +
       (image_root.empty() ? "" : ", colours from " + image_root) + ")");
}

}  // namespace

void AddExportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export",
      "Export a model for dense reconstruction and viewing:\n"
      "  openmvs             OUT/scene.mvs + OUT/images (undistorted), for OpenMVS\n"
      "  colmap-undistorted  OUT/images + OUT/sparse (PINHOLE) + OUT/stereo, COLMAP's dense workspace,\n"
      "                      also read by Gaussian splatting and NeRF tools\n"
      "  colmap              OUT as a COLMAP sparse model (cameras as estimated, distortion kept)\n"
      "  ply                 OUT.ply, the points (coloured from the images when given, else as in the model)\n"
      "  json                OUT.json (or .bin), OpenMVG sfm_data\n"
      "Point colours are the mean image colour over each point's observations whenever images are given.");
  auto args = std::make_shared<ExportArguments>();
  cmd->add_option("--model,--input_path,-i", args->model,
                  "Model to export (COLMAP folder, sfm_data.json/.bin, scene.mvs)")
      ->required();
  cmd->add_option("--images,--image_path", args->images,
                  "Folder of the original images (default: the model's root path)");
  cmd->add_option("--format", args->format, "openmvs, colmap-undistorted, colmap, ply or json")
      ->required()
      ->check(CLI::IsMember({"openmvs", "colmap", "colmap-undistorted", "ply", "json"}));
  cmd->add_option("--output,--output_path,-o", args->output, "Folder or file to write (replaced atomically)")
      ->required();
  cmd->add_flag("--keep_all_pixels", args->keep_all_pixels,
                "Undistorted images keep every source pixel (black borders) instead of the default crop with "
                "no black borders");
  cmd->add_option("--jpeg_quality", args->jpeg_quality, "Quality of undistorted JPEG images")
      ->check(RangeValue(1, 100))
      ->capture_default_str();
  cmd->add_option("--output_type", args->output_type, "--format colmap: BIN or TXT")
      ->check(CLI::IsMember({"BIN", "TXT"}))
      ->capture_default_str();
  cmd->add_option("--num_threads", args->num_threads,
                  "Threads for reading and undistorting images (output does not depend on it)")
      ->check(PositiveValue())
      ->capture_default_str();
  AddOverwriteFlag(cmd, &args->overwrite, OverwriteMeans::kReplaceTheFolder);
  cmd->callback([args]() { RunExport(*args); });
}

}  // namespace prunesfm
