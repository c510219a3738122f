// prunesfm convert: converts a reconstruction between the model formats the project reads and
// writes. Each side's format comes from its path (io/model_io.hpp): *.json / *.bin = OpenMVG
// sfm_data, *.ply = PLY, *.txt = gt_cameras.txt, a folder = COLMAP sparse model.
#include <CLI/CLI.hpp>

#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"

namespace prunesfm {
namespace {

struct ConvertArguments {
  std::string input;
  std::string output;
  std::string output_type = "BIN";
  bool overwrite = false;
};

void RunConvert(const ConvertArguments& args) {
  if (args.output.empty()) throw sfm_pruning::Error("convert: the output path is empty");
  RefuseOutputOverInput(args.output, {args.input});
  if (sfm_pruning::OutputModelFormat(args.output) == sfm_pruning::ModelFormat::kColmapModel) {
    sfm_pruning::CheckOutputFolder(args.output, sfm_pruning::OutputFolderKind::kColmapModel, args.overwrite);
  }
  const sfm_pruning::SfmData data = sfm_pruning::ReadModel(args.input);
  sfm_pruning::ModelWriteOptions options;
  options.colmap_text = args.output_type == "TXT";
  sfm_pruning::WriteModel(data, args.output, options);
  Info("wrote " + sfm_pruning::ModelFormatName(sfm_pruning::OutputModelFormat(args.output)) + " " + args.output +
       " (" + std::to_string(data.views.size()) + " views, " + std::to_string(data.poses.size()) + " poses, " +
       std::to_string(data.structure.size()) + " points)");
}

}  // namespace

void AddConvertCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert",
      "Convert a model between OpenMVG sfm_data.json/.bin, a COLMAP sparse model folder, gt_cameras.txt and PLY.\n"
      "Formats follow the paths: *.json/*.bin = sfm_data, *.ply = PLY, *.txt = gt_cameras.txt,\n"
      "anything else = a COLMAP model folder (cameras/images/points3D).");
  auto args = std::make_shared<ConvertArguments>();
  cmd->add_option("--input_path,--input,-i", args->input, "Model to read")->required();
  cmd->add_option("--output_path,--output,-o", args->output, "Model to write (replaced atomically)")->required();
  cmd->add_option("--output_type", args->output_type, "COLMAP folder encoding: BIN or TXT")
      ->check(CLI::IsMember({"BIN", "TXT"}))
      ->capture_default_str();
  AddOverwriteFlag(cmd, &args->overwrite, OverwriteMeans::kReplaceTheFolder);
  cmd->callback([args]() { RunConvert(*args); });
}

}  // namespace prunesfm
