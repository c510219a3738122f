// prunesfm reconstruct: an OpenMVG project (sfm_data.json + features + matches) or a COLMAP
// database -> verified view graph -> GLOBAL engine -> sfm_data.json, sparse/0, PLY, timings.
#include <CLI/CLI.hpp>

#include <chrono>

#include "sfm_pruning/util/error.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/reconstruction_pipeline.hpp"

namespace prunesfm {
namespace {

struct ReconstructArguments {
  EngineSettings engine;
  std::string sfm_data;
  std::string matches_dir;
  std::string match_file;
  std::string database;
  std::string image_path;
  std::string output;
  bool overwrite = false;
};

void RunReconstruct(const ReconstructArguments& args) {
  if (args.sfm_data.empty() == args.database.empty()) {
    throw sfm_pruning::Error("reconstruct: give either --sfm_data with --matches_dir, or --database");
  }
  if (!args.image_path.empty() && args.database.empty()) {
    throw sfm_pruning::Error("reconstruct: --image_path goes with --database (an OpenMVG project names its image folder)");
  }
  if (!args.sfm_data.empty() && args.matches_dir.empty()) {
    throw sfm_pruning::Error("reconstruct: --sfm_data needs --matches_dir");
  }
  PrepareRunFolder(args.output, args.overwrite);
  const auto start = std::chrono::steady_clock::now();
  const sfm_pruning::ReconstructionInput input =
      args.database.empty()
          ? sfm_pruning::ReadOpenMvgInput(args.sfm_data, args.matches_dir, args.match_file, ProgressOnStderr())
          : ReadDatabaseInput(args.database, args.image_path, args.engine);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RunReconstruction(args.engine, input, args.output, read_seconds);
}

}  // namespace

void AddReconstructCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "reconstruct",
      "Global SfM from an OpenMVG project (--sfm_data + --matches_dir) or a COLMAP database (--database).\n"
      "Putative matches are verified first; a database's two-view geometries are used as they are.\n"
      "Writes OUT/sfm_data.json, OUT/sparse/0 (COLMAP binary), OUT/cloud_and_poses.ply, OUT/timings.json.");
  auto args = std::make_shared<ReconstructArguments>();
  cmd->add_option("--sfm_data", args->sfm_data, "OpenMVG sfm_data.json/.bin with views and intrinsics");
  cmd->add_option("--matches_dir", args->matches_dir, "Folder of the .feat files and the match file");
  cmd->add_option("--match_file", args->match_file, "Match file (default: matches.e/f/putative .bin/.txt)");
  cmd->add_option("--database,--database_path", args->database, "COLMAP database.db");
  cmd->add_option("--image_path", args->image_path,
                  "With --database: image folder (the points are coloured from its images when they are all there)");
  cmd->add_option("--output,--output_path,-o", args->output, "Output folder")->required();
  AddOverwriteFlag(cmd, &args->overwrite, OverwriteMeans::kWriteInto);
  AddEngineOptions(cmd, &args->engine);
  cmd->callback([args]() { RunReconstruct(*args); });
}

}  // namespace prunesfm
