// prunesfm run: GLOMAP-style entry point: a COLMAP database (+ image folder) -> OUT/sparse/0
// (and the other outputs of reconstruct). The images are not read.
#include <CLI/CLI.hpp>

#include <chrono>

#include "software/commands.hpp"
#include "software/commands/reconstruction_pipeline.hpp"

namespace prunesfm {
namespace {

struct RunArguments {
  EngineSettings engine;
  std::string database;
  std::string image_path;
  std::string output;
};

void RunRun(const RunArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  ReconstructionInput input = ReadColmapInput(args.database);
  input.scene.root_path = args.image_path;
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RunReconstruction(args.engine, input, args.output, read_seconds);
}

}  // namespace

void AddRunCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "run", "Reconstruct from a COLMAP database (verified two-view geometries, or matches to verify) into\n"
             "OUT/sparse/0, like 'glomap mapper'. The images are only recorded as the root path.");
  auto args = std::make_shared<RunArguments>();
  cmd->add_option("--database_path,--database", args->database, "COLMAP database.db")->required();
  cmd->add_option("--image_path", args->image_path, "Image folder (recorded, not read)")->required();
  cmd->add_option("--output_path,--output", args->output, "Output folder")->required();
  AddEngineOptions(cmd, &args->engine);
  cmd->callback([args]() { RunRun(*args); });
}

}  // namespace prunesfm
