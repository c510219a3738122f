// prunesfm run: the main command.
//   prunesfm run IMAGES_DIR OUT_DIR   images -> init -> features -> match -> engine, resumable
//   prunesfm run                      the same on the default dataset (templeSparseRing) into out/default
//   prunesfm run --database DB [--image_path DIR] --output_path OUT   GLOMAP-style: a COLMAP database in
#include <CLI/CLI.hpp>

#include <chrono>

#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/default_dataset.hpp"
#include "software/commands/front_end_stages.hpp"
#include "software/commands/reconstruction_pipeline.hpp"
#include "software/commands/run_manifest.hpp"
#include "software/help_format.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;
using sfm_pruning::Error;

struct RunArguments {
  EngineSettings engine;
  InitSettings init;
  FeatureSettings features;
  MatchSettings match;
  bool force = false;
  bool no_colmap_database = false;
  bool overwrite = false;
  std::string images;
  std::string output_dir;
  std::string database;
  std::string image_path;
  std::string output;
};

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void RunFromDatabase(const RunArguments& args) {
  if (args.output.empty()) throw Error("run: --database needs --output_path");
  PrepareRunFolder(args.output, args.overwrite);
  const auto start = std::chrono::steady_clock::now();
  const sfm_pruning::ReconstructionInput input = ReadDatabaseInput(args.database, args.image_path, args.engine);
  RunReconstruction(args.engine, input, args.output, SecondsSince(start));
}

// Runs `stage` unless the manifest says it finished with the same key and its outputs exist.
template <typename Stage>
FrontEndStageTiming RunOrReuse(RunManifest* manifest, const std::string& name, const std::string& key,
                               const std::vector<fs::path>& outputs, bool force, Stage&& stage) {
  if (!force && manifest->IsDone(name, key, outputs)) {
    Info(name + ": reusing the previous run's result (inputs and options unchanged)");
    return {name, manifest->Seconds(name), true};
  }
  const auto start = std::chrono::steady_clock::now();
  stage();
  const double seconds = SecondsSince(start);
  manifest->MarkDone(name, key, seconds);
  return {name, seconds, false};
}

void RunFromImages(const RunArguments& args, const fs::path& images, const fs::path& out) {
  const int threads = sfm_pruning::ResolveThreadCount(args.engine.num_threads);
  const fs::path matches_dir = out / "matches";
  const fs::path sfm_path = matches_dir / "sfm_data.json";
  PrepareRunFolder(out, args.overwrite);
  RunManifest manifest(out / "run_manifest.json");
  using sfm_pruning::SfmDataParts;
  const auto read_scene = [&]() {
    return sfm_pruning::ReadSfmData(sfm_path, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  };

  std::vector<FrontEndStageTiming> timings;
  const std::string init_key =
      HashKey(FolderFingerprint(images) + SettingsKey(args.init) + FileFingerprint(args.init.k_file));
  timings.push_back(RunOrReuse(&manifest, "init", init_key, {sfm_path}, args.force,
                               [&]() { RunInitStage(args.init, images, sfm_path, threads); }));
  const size_t num_images = read_scene().views.size();
  if (num_images < 2) {
    throw sfm_pruning::FileError(images.string(), "only " + std::to_string(num_images) +
                                                      " image decodes; a reconstruction needs at least two");
  }

  const std::string features_key = HashKey(init_key + SettingsKey(args.features));
  std::optional<sfm_pruning::FeaturesPerView> features;
  timings.push_back(RunOrReuse(
      &manifest, "features", features_key, {matches_dir / sfm_pruning::kImageDescriberFileName}, args.force,
      [&]() { features = RunFeatureStage(args.features, read_scene(), matches_dir, threads); }));

  MatchSettings match = args.match;
  match.seed = args.engine.seed;
  match.max_epipolar_error_deg = args.engine.max_epipolar_error_deg;
  match.verification_precision_ratio = args.engine.verification_precision_ratio;
  const std::string match_key = HashKey(features_key + SettingsKey(match) + FileFingerprint(match.pair_list));
  // OUT/database.db: the same features and matches for COLMAP's and GLOMAP's mappers.
  const fs::path database = args.no_colmap_database ? fs::path() : out / "database.db";
  std::vector<fs::path> match_outputs = {matches_dir / "matches.e.bin"};
  if (!database.empty()) match_outputs.push_back(database);
  timings.push_back(RunOrReuse(&manifest, "match", match_key, match_outputs, args.force, [&]() {
    const sfm_pruning::SfmData scene = read_scene();
    if (!features) features = sfm_pruning::ReadOpenMvgFeatures(scene, matches_dir, true, ProgressOnStderr());
    RunMatchStage(match, scene, &*features, matches_dir, threads, database);
  }));
  features.reset();  // descriptors are not needed any more

  const auto start = std::chrono::steady_clock::now();
  sfm_pruning::ReconstructionInput input =
      sfm_pruning::ReadOpenMvgInput(sfm_path, matches_dir, matches_dir / "matches.e.bin", ProgressOnStderr());
  // Problems of the matches are the images' (the run wrote the match file itself).
  input.source = images.string();
  RunReconstruction(args.engine, input, out, SecondsSince(start), timings);
}

// Without ../shared: the synthetic `clean` scene (features and matches, no images) through the
// same engine, so that a fresh checkout still runs end to end.
void RunSyntheticFallback(const RunArguments& args, const fs::path& out) {
  PrepareRunFolder(out, args.overwrite);
  sfm_pruning::SyntheticSceneOptions options;
  options.scene = "clean";
  options.seed = args.engine.seed;
  const auto start = std::chrono::steady_clock::now();
  const sfm_pruning::SyntheticScene scene = sfm_pruning::GenerateSyntheticScene(options, ProgressOnStderr());
  sfm_pruning::ReconstructionInput input;
  input.source = "synthetic scene 'clean'";
  input.scene.views = scene.ground_truth.views;
  input.scene.intrinsics = scene.ground_truth.intrinsics;
  input.features = scene.features;
  input.putative = scene.putative_matches;
  RunReconstruction(args.engine, input, out, SecondsSince(start));
}

void RunRun(const RunArguments& args) {
  if (!args.database.empty()) {
    if (!args.images.empty()) throw Error("run: give either IMAGES_DIR OUT_DIR or --database, not both");
    RunFromDatabase(args);
    return;
  }
  if (!args.image_path.empty() || !args.output.empty()) {
    throw Error("run: --image_path and --output_path go with --database; for images give IMAGES_DIR OUT_DIR");
  }
  if (!args.images.empty()) {
    if (args.output_dir.empty()) throw Error("run: IMAGES_DIR needs an OUT_DIR");
    RunFromImages(args, args.images, args.output_dir);
    return;
  }
  const fs::path out = "out/default";
  if (const std::optional<fs::path> images = FindDefaultDataset()) {
    Info("no input given: running on the default dataset " + images->string() + " into " + out.string());
    RunFromImages(args, *images, out);
    return;
  }
  Info(std::string("no input given and the default dataset (shared/") + kDefaultDatasetRelative +
       ") was not found beside the project: running on the generated synthetic scene 'clean' (features and "
       "matches, no images) into " + out.string());
  RunSyntheticFallback(args, out);
}

}  // namespace

void AddRunCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "run",
      "The whole pipeline. 'prunesfm run IMAGES_DIR OUT_DIR': init, features, match (into OUT/matches, reused\n"
      "when their inputs and options did not change: OUT/run_manifest.json), then the engine: OUT/sfm_data.json,\n"
      "OUT/sparse/0, OUT/cloud_and_poses.ply, OUT/timings.json. Without arguments: the default dataset\n"
      "(../shared/" + std::string(kDefaultDatasetRelative) + ") into out/default.\n"
      "'prunesfm run --database DB [--image_path DIR] --output_path OUT': from a COLMAP database, like 'glomap mapper'.");
  auto args = std::make_shared<RunArguments>();
  cmd->add_option("IMAGES_DIR", args->images, "Folder of images");
  cmd->add_option("OUT_DIR", args->output_dir, "Output folder");
  cmd->add_option("--database_path,--database", args->database, "COLMAP database.db");
  cmd->add_option("--image_path", args->image_path,
                  "With --database: image folder (the points are coloured from its images when they are all "
                  "there; without it, or for a synthetic database, they stay grey)");
  cmd->add_option("--output_path,--output", args->output, "With --database: output folder");
  cmd->add_flag("--force", args->force, "Rerun every stage, ignoring OUT/run_manifest.json");
  cmd->add_flag("--no_colmap_database", args->no_colmap_database,
                "From images: do not write OUT/database.db (the features and matches for colmap mapper, glomap "
                "mapper or prunesfm prune; it repeats the descriptors of OUT/matches)")
      ->group(kExpertOptionsGroup);
  AddOverwriteFlag(cmd, &args->overwrite, OverwriteMeans::kWriteInto);
  AddEngineOptions(cmd, &args->engine);
  AddInitOptions(cmd, &args->init);
  AddFeatureOptions(cmd, &args->features);
  AddMatchOptions(cmd, &args->match, false);
  cmd->callback([args]() { RunRun(*args); });
}

}  // namespace prunesfm
