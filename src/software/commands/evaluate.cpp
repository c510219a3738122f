// prunesfm evaluate: accuracy of a reconstruction against ground truth (docs/evaluation.md).
// Prints a text report on stdout and, with --json, writes the same numbers as JSON.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"

namespace prunesfm {
namespace {

struct EvaluateArguments {
  std::string estimate;
  std::string ground_truth;
  std::vector<double> thresholds_deg = {3.0, 5.0, 10.0};
  std::string json;
  uint64_t seed = 0;
  double inlier_threshold_scene_fraction = sfm_pruning::RobustSimilarityOptions().inlier_threshold_scene_fraction;
};

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string TextReport(const EvaluateArguments& args, const sfm_pruning::EvaluationReport& report) {
  std::string text = "estimate:      " + args.estimate + "\nground truth:  " + args.ground_truth + "\n";
  text += "registered:    " + std::to_string(report.num_registered_images) + " / " +
          std::to_string(report.num_ground_truth_images) + " ground-truth images";
  if (report.num_unmatched_estimate_images > 0) {
    text += " (" + std::to_string(report.num_unmatched_estimate_images) + " estimate images have no ground truth)";
  }
  text += "\npairs:         " + std::to_string(report.num_pairs) + " (" + std::to_string(report.num_failed_pairs) +
          " with an unregistered image)\n";
  for (const sfm_pruning::AucAtThreshold& auc : report.auc) {
    text += "AUC@" + Format("%g", auc.threshold_deg) + " deg:" + std::string(auc.threshold_deg < 10 ? "  " : " ") +
            Format("%.2f", auc.auc_percent) + "\n";
  }
  if (!report.alignment) {
    text += "alignment:     not possible (fewer than 3 registered cameras in general position)\n";
    return text;
  }
  const sfm_pruning::AlignmentErrors& a = *report.alignment;
  text += "alignment:     " + std::to_string(a.num_inliers) + " inlier cameras, scale " + Format("%.6g", a.transform.scale) +
          "\nposition error (ground-truth units): median " + Format("%.6g", a.median_position_error) + ", mean " +
          Format("%.6g", a.mean_position_error) + "\nrotation error (deg):                median " +
          Format("%.4f", a.median_rotation_error_deg) + ", mean " + Format("%.4f", a.mean_rotation_error_deg) + "\n";
  return text;
}

nlohmann::json JsonReport(const EvaluateArguments& args, const sfm_pruning::EvaluationReport& report) {
  nlohmann::json json;
  json["estimate"] = args.estimate;
  json["ground_truth"] = args.ground_truth;
  json["seed"] = args.seed;
  json["num_ground_truth_images"] = report.num_ground_truth_images;
  json["num_registered_images"] = report.num_registered_images;
  json["num_estimate_images"] = report.num_estimate_images;
  json["num_unmatched_estimate_images"] = report.num_unmatched_estimate_images;
  json["num_pairs"] = report.num_pairs;
  json["num_failed_pairs"] = report.num_failed_pairs;
  json["auc"] = nlohmann::json::array();
  for (const sfm_pruning::AucAtThreshold& auc : report.auc) {
    json["auc"].push_back({{"threshold_deg", auc.threshold_deg}, {"auc_percent", auc.auc_percent}});
  }
  if (report.alignment) {
    const sfm_pruning::AlignmentErrors& a = *report.alignment;
    json["alignment"] = {{"num_inliers", a.num_inliers},
                         {"inlier_threshold", a.inlier_threshold},
                         {"scale", a.transform.scale},
                         {"median_position_error", a.median_position_error},
                         {"mean_position_error", a.mean_position_error},
                         {"median_rotation_error_deg", a.median_rotation_error_deg},
                         {"mean_rotation_error_deg", a.mean_rotation_error_deg}};
  } else {
    json["alignment"] = nullptr;
  }
  return json;
}

void RunEvaluate(const EvaluateArguments& args) {
  for (double threshold : args.thresholds_deg) {
    if (!(threshold > 0.0)) throw sfm_pruning::Error("--thresholds: every threshold must be > 0 degrees");
  }
  const sfm_pruning::SfmData estimate = sfm_pruning::ReadModel(args.estimate);
  const sfm_pruning::SfmData ground_truth = sfm_pruning::ReadModel(args.ground_truth);
  sfm_pruning::EvaluationOptions options;
  options.auc_thresholds_deg = args.thresholds_deg;
  options.alignment.seed = args.seed;
  options.alignment.inlier_threshold_scene_fraction = args.inlier_threshold_scene_fraction;
  const sfm_pruning::EvaluationReport report =
      sfm_pruning::EvaluateModel(estimate, ground_truth, options, args.estimate, args.ground_truth);
  std::fputs(TextReport(args, report).c_str(), stdout);
  if (!args.json.empty()) {
    const std::string text = JsonReport(args, report).dump(2) + "\n";
    sfm_pruning::WriteFileAtomically(args.json, /*binary=*/false, [&](std::ostream& out) { out << text; });
    Info("wrote " + args.json);
  }
}

}  // namespace

void AddEvaluateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "evaluate",
      "Pose accuracy of a reconstruction against ground truth: AUC of pairwise relative pose errors, "
      "registered images, errors after similarity alignment");
  auto args = std::make_shared<EvaluateArguments>();
  cmd->add_option("--estimate,-e", args->estimate,
                  "Estimated model: COLMAP model folder, sfm_data.json/.bin or gt_cameras.txt")
      ->required();
  cmd->add_option("--ground_truth,-g", args->ground_truth, "Ground-truth model (same formats; usually gt_cameras.txt)")
      ->required();
  cmd->add_option("--thresholds", args->thresholds_deg, "AUC thresholds in degrees, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--json", args->json, "Also write the report as JSON to this file");
  cmd->add_option("--seed", args->seed, "Seed of the alignment's RANSAC")->check(SeedValue())->capture_default_str();
  cmd->add_option("--inlier_threshold_scene_fraction", args->inlier_threshold_scene_fraction,
                  "Alignment inlier distance as a fraction of the ground-truth scene radius")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->callback([args]() { RunEvaluate(*args); });
}

}  // namespace prunesfm
