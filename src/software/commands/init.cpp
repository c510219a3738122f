// prunesfm init: a folder of images -> sfm_data.json (views + intrinsics) and camera_priors.json,
// like OpenMVG's SfMInit_ImageListing.
#include <CLI/CLI.hpp>

#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_checks.hpp"
#include "software/commands.hpp"
#include "software/commands/front_end_stages.hpp"

namespace prunesfm {
namespace {

struct InitArguments {
  InitSettings settings;
  std::string image_dir;
  std::string output;
  int num_threads = 0;
};

}  // namespace

void AddInitCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "init",
      "List a folder of images into an OpenMVG sfm_data.json (views and intrinsics) plus camera_priors.json.\n"
      "Focal length: --focal, else --k_file, else EXIF (focal mm with --sensor_width, the 35 mm equivalent, or the\n"
      "focal-plane resolution), else the guess 1.2 x max(width, height), marked untrusted. Images that do not decode\n"
      "are reported and skipped.");
  auto args = std::make_shared<InitArguments>();
  cmd->add_option("--image_dir,-i", args->image_dir, "Folder of images (jpg, png, tif, ...)")->required();
  cmd->add_option("--output,--output_path,-o", args->output,
                  "sfm_data.json to write (e.g. OUT/matches/sfm_data.json)")->required();
  cmd->add_option("--num_threads", args->num_threads, "Threads (default: every core)")->check(PositiveValue());
  AddInitOptions(cmd, &args->settings);
  cmd->callback([args]() {
    RunInitStage(args->settings, args->image_dir, args->output, sfm_pruning::ResolveThreadCount(args->num_threads));
  });
}

}  // namespace prunesfm
