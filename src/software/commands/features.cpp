// prunesfm features: SIFT (OpenCV) for every view of an sfm_data.json, written as OpenMVG's
// .feat/.desc files and image_describer.json.
#include <CLI/CLI.hpp>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_checks.hpp"
#include "software/commands.hpp"
#include "software/commands/front_end_stages.hpp"

namespace prunesfm {
namespace {

struct FeaturesArguments {
  FeatureSettings settings;
  std::string sfm_data;
  std::string output;
  int num_threads = 0;
};

void RunFeatures(const FeaturesArguments& args) {
  using sfm_pruning::SfmDataParts;
  const sfm_pruning::SfmData scene =
      sfm_pruning::ReadSfmData(args.sfm_data, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  RunFeatureStage(args.settings, scene, args.output, sfm_pruning::ResolveThreadCount(args.num_threads));
}

}  // namespace

void AddFeaturesCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "features",
      "SIFT features (OpenCV; RootSIFT by default) of every image of an sfm_data.json, in parallel over images,\n"
      "written in OpenMVG's format: <output>/<image>.feat, .desc and image_describer.json.");
  auto args = std::make_shared<FeaturesArguments>();
  cmd->add_option("--sfm_data,-s", args->sfm_data, "sfm_data.json from 'prunesfm init'")->required();
  cmd->add_option("--output,--output_path,-o", args->output,
                  "Folder of the feature files (OpenMVG's matches folder)")->required();
  cmd->add_option("--num_threads", args->num_threads, "Threads (default: every core)")->check(PositiveValue());
  AddFeatureOptions(cmd, &args->settings);
  cmd->callback([args]() { RunFeatures(*args); });
}

}  // namespace prunesfm
