// prunesfm epipolar: the paper's epipolar check of one point as a picture (docs/report.md).
#include <CLI/CLI.hpp>

#include <filesystem>

#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/report/epipolar_check.hpp"
#include "sfm_pruning/report/epipolar_image.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/report_arguments.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;

struct EpipolarArguments {
  std::string model;
  std::string images;
  std::string image;
  std::string point;
  std::vector<std::string> others;
  size_t max_others = 3;
  std::string ground_truth;
  std::string output;
  int height = 360;
};

void RunEpipolar(const EpipolarArguments& args) {
  const std::string extension = fs::path(args.output).extension().string();
  if (extension != ".png" && extension != ".jpg") {
    throw sfm_pruning::Error(args.output + ": the output must end in .png or .jpg");
  }
  if (!args.images.empty() && !fs::is_directory(args.images)) {
    throw sfm_pruning::FileError(args.images, "no such image folder");
  }
  const sfm_pruning::SfmData model = sfm_pruning::ReadModel(args.model);
  std::optional<sfm_pruning::SfmData> truth;
  if (!args.ground_truth.empty()) truth = sfm_pruning::ReadModel(args.ground_truth);
  try {
    const Eigen::Vector2d point =
        args.point.empty() ? sfm_pruning::ChooseCheckPoint(model, args.image) : ParsePixel(args.point, "--point");
    sfm_pruning::EpipolarCheckOptions options;
    options.max_other_views = args.max_others;
    const std::vector<std::string> others =
        args.others.empty() ? sfm_pruning::ImagesSeeingRegion(model, args.image, point, options) : args.others;
    if (others.empty()) throw sfm_pruning::Error("no other registered image shares points with " + args.image);
    const sfm_pruning::EpipolarCheck check =
        sfm_pruning::ComputeEpipolarCheck(model, args.image, point, others, truth ? &*truth : nullptr, options);
    sfm_pruning::EpipolarImageOptions image_options;
    image_options.panel_height = args.height;
    if (!args.images.empty()) image_options.images_dir = fs::path(args.images);
    const std::vector<uint8_t> bytes = sfm_pruning::RenderEpipolarCheck(check, model, image_options, extension);
    sfm_pruning::WriteFileAtomically(args.output, true, [&](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    });
    std::string list;
    for (const std::string& other : others) list += (list.empty() ? "" : ", ") + other;
    Info("epipolar lines of (" + std::to_string(point.x()) + ", " + std::to_string(point.y()) + ") in " + args.image +
         " drawn in " + list + "; wrote " + args.output);
  } catch (const sfm_pruning::Error& e) {
    RethrowNamingSource(e, args.model, {args.model, args.images, args.ground_truth, args.output});
  }
}

}  // namespace

void AddEpipolarCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "epipolar", "Draw the epipolar check of a point: the point in image A and its epipolar lines (red) in the\n"
                  "other registered images that see the region, with the true lines (dashed green) when ground\n"
                  "truth is given, as a PNG.");
  auto args = std::make_shared<EpipolarArguments>();
  cmd->add_option("--model", args->model, "Model: COLMAP folder, sfm_data.json/.bin (e.g. OUT/sfm_data.json)")
      ->required();
  cmd->add_option("--image", args->image, "Reference image, as named in the model")->required();
  cmd->add_option("--point", args->point, "Pixel x,y in the reference image (default: a well-tracked feature)");
  cmd->add_option("--images,--image_path", args->images,
                  "Image folder (default: each view drawn as its observed features)");
  cmd->add_option("--others", args->others, "Images to draw the lines in, comma-separated (default: those that see the region)")
      ->delimiter(',');
  cmd->add_option("--max_others", args->max_others, "How many other images to choose")->capture_default_str();
  cmd->add_option("--ground_truth", args->ground_truth, "gt_cameras.txt (or any model) for the true lines");
  cmd->add_option("--height", args->height, "Height of each panel in pixels")
      ->check(RangeValue(64, 4096))
      ->capture_default_str();
  cmd->add_option("--output,--output_path,-o", args->output, "Output picture (.png or .jpg)")->required();
  cmd->callback([args]() { RunEpipolar(*args); });
}

}  // namespace prunesfm
