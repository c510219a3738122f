// prunesfm convert: converts a reconstruction between the model formats the project reads and
// writes, choosing each format from the path (extension, or folder content for COLMAP models).
#include <CLI/CLI.hpp>

#include "sfm_pruning/io/ply.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"

namespace prunesfm {

void AddConvertCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("convert", "Convert a model between sfm_data.json/.bin, a COLMAP model folder and PLY");
  auto input = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  cmd->add_option("--input,--input_path,-i", *input, "Input model")->required();
  cmd->add_option("--output,--output_path,-o", *output, "Output model")->required();
  cmd->callback([input, output]() {
    const sfm_pruning::SfmData data = sfm_pruning::ReadPlyPoints(*input);
    sfm_pruning::WritePly(data, *output);
    Info("wrote " + *output);
  });
}

}  // namespace prunesfm
