// prunesfm report: the self-contained HTML page of a run, optionally next to another run
// (docs/report.md).
#include <CLI/CLI.hpp>

#include <filesystem>

#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/report/html_report.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/report_arguments.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;

struct ReportArguments {
  std::string run;
  std::string compare;
  std::string ground_truth;
  std::string images;
  std::string output;
  std::string title;
  std::vector<std::string> checks;
  size_t num_checks = 2;
  size_t other_views = 3;
  uint64_t seed = 0;
};

void RunReport(const ReportArguments& args) {
  sfm_pruning::HtmlReportInput input;
  input.title = args.title;
  input.seed = args.seed;
  input.num_auto_checks = args.num_checks;
  input.max_other_views = args.other_views;
  for (const std::string& check : args.checks) input.checks.push_back(ParseCheck(check, "--check"));
  input.runs.push_back(sfm_pruning::ReadRunFolder(args.run));
  if (!args.compare.empty()) input.runs.push_back(sfm_pruning::ReadRunFolder(args.compare));
  if (!args.ground_truth.empty()) {
    input.ground_truth = sfm_pruning::ReadModel(args.ground_truth);
    input.ground_truth_source = args.ground_truth;
  }
  if (!args.images.empty()) {
    if (!fs::is_directory(args.images)) throw sfm_pruning::FileError(args.images, "no such image folder");
    input.images_dir = fs::path(args.images);
    for (sfm_pruning::RunFolder& run : input.runs) {
      sfm_pruning::ColorLandmarksFromImages(&run.model, *input.images_dir, 1, ProgressOnStderr());
    }
  }
  std::string html;
  try {
    html = sfm_pruning::BuildHtmlReport(input);
  } catch (const sfm_pruning::Error& e) {
    RethrowNamingSource(e, args.run, {args.run, args.compare, args.images, args.ground_truth});
  }
  sfm_pruning::WriteFileAtomically(args.output, false, [&](std::ostream& out) { out << html; });
  Info("wrote " + args.output + " (" + std::to_string(html.size() / 1024) + " KiB)");
}

}  // namespace

void AddReportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "report", "Write a self-contained HTML report of a run folder (prunesfm run/reconstruct output): view graph\n"
                "before and after pruning, top view of cameras and points, epipolar checks, timings, AUC with\n"
                "ground truth. --compare puts a second run (e.g. GLOBAL next to GLOBAL_PRUNED) beside it.");
  auto args = std::make_shared<ReportArguments>();
  cmd->add_option("--run", args->run, "Run folder (sfm_data.json or sparse/0, timings.json, view_graph.json, ...)")
      ->required();
  cmd->add_option("--compare", args->compare, "A second run folder of the same scene, shown side by side");
  cmd->add_option("--ground_truth", args->ground_truth, "gt_cameras.txt (or any model): AUC, aligned top view");
  cmd->add_option("--images,--image_path", args->images,
                  "Image folder: real pictures in the epipolar checks, coloured points");
  cmd->add_option("--check", args->checks, "Epipolar check IMAGE:x,y (repeatable; default: --num_checks chosen)");
  cmd->add_option("--num_checks", args->num_checks, "Epipolar checks chosen when no --check is given")
      ->capture_default_str();
  cmd->add_option("--other_views", args->other_views, "Images each epipolar check draws lines in")
      ->capture_default_str();
  cmd->add_option("--title", args->title, "Page title (default: the run folder's name)");
  cmd->add_option("--seed", args->seed, "Seed of the graph layout and the ground-truth alignment")
      ->check(SeedValue())
      ->capture_default_str();
  cmd->add_option("--output,--output_path,-o", args->output, "Output HTML file")->required();
  cmd->callback([args]() { RunReport(*args); });
}

}  // namespace prunesfm
