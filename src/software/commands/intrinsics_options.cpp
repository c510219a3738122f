#include "software/commands/intrinsics_options.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>

#include "software/cli_support.hpp"

namespace prunesfm {
namespace {

std::string Pixels(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f px", value);
  return text;
}

}  // namespace

void AddIntrinsicsOptions(CLI::App* cmd, IntrinsicsSettings* settings) {
  auto* group = cmd->add_option_group("Intrinsics");
  group
      ->add_option("--refine_intrinsics", settings->cameras,
                   "Cameras whose intrinsics are estimated. AUTO: all but those calibrated with a K file; a\n"
                   "camera whose focal is only a guess (COLMAP's prior_focal_length = 0, images without EXIF)\n"
                   "is calibrated on the view graph and refined in full, one with an EXIF focal has focal and\n"
                   "distortion refined. GUESSED: only the guessed ones. ALL: every camera in full. NONE")
      ->check(CLI::IsMember({"AUTO", "GUESSED", "ALL", "NONE"}))
      ->capture_default_str();
  group
      ->add_option("--refine_focal", settings->focal,
                   "For those cameras: refine the focal in bundle adjustment, after calibrating it from the view\n"
                   "graph's fundamental matrices before verification when it is only a guess")
      ->capture_default_str();
  group
      ->add_option("--refine_distortion", settings->distortion,
                   "For those cameras: refine the distortion coefficients in bundle adjustment")
      ->capture_default_str();
  group
      ->add_option("--refine_principal_point", settings->principal_point,
                   "For those cameras: refine the principal point in bundle adjustment")
      ->capture_default_str();
}

std::set<sfm_pruning::IndexT> RefinedIntrinsics(const IntrinsicsSettings& settings, const ReconstructionInput& input) {
  if (settings.cameras == "NONE") return {};
  if (settings.cameras == "GUESSED") return input.guessed_focal;
  std::set<sfm_pruning::IndexT> refined;
  for (const auto& [intrinsic_id, intrinsics] : input.scene.intrinsics) {
    if (settings.cameras == "ALL" || input.k_file_intrinsics.count(intrinsic_id) == 0) refined.insert(intrinsic_id);
  }
  return refined;
}

std::set<sfm_pruning::IndexT> FocalsToCalibrate(const IntrinsicsSettings& settings,
                                                    const ReconstructionInput& input) {
  std::set<sfm_pruning::IndexT> refined = RefinedIntrinsics(settings, input);
  if (settings.cameras != "AUTO") return refined;
  std::set<sfm_pruning::IndexT> guessed;
  for (const sfm_pruning::IndexT id : refined) {
    if (input.guessed_focal.count(id) > 0) guessed.insert(id);
  }
  return guessed;
}

sfm_pruning::BundleAdjustmentOptions RefiningBundleOptions(const IntrinsicsSettings& settings,
                                                           const ReconstructionInput& input,
                                                           const std::set<sfm_pruning::IndexT>& refined) {
  sfm_pruning::BundleAdjustmentOptions bundle;
  bundle.refine_focal = settings.focal;
  bundle.refine_distortion = settings.distortion;
  bundle.refine_principal_point = settings.principal_point;
  for (const auto& [intrinsic_id, intrinsics] : input.scene.intrinsics) {
    if (refined.count(intrinsic_id) == 0) {
      bundle.constant_intrinsics.insert(intrinsic_id);
    } else if (settings.cameras == "AUTO" && input.guessed_focal.count(intrinsic_id) == 0) {
      bundle.constant_principal_point.insert(intrinsic_id);
    }
  }
  return bundle;
}

void ReportCalibration(const sfm_pruning::FocalCalibrationReport& report) {
  for (const sfm_pruning::IntrinsicFocalCalibration& entry : report.intrinsics) {
    std::string line = "focal calibration: camera " + std::to_string(entry.intrinsic_id) + " (" +
                       std::to_string(entry.num_pairs) + " pairs): ";
    if (entry.accepted) {
      line += Pixels(entry.prior_focal) + " -> " + Pixels(entry.estimated_focal);
    } else {
      line += "kept " + Pixels(entry.prior_focal) + ": " + entry.reason;
      if (entry.estimated_focal > 0.0) line += " (estimate " + Pixels(entry.estimated_focal) + ")";
    }
    char gaps[96];
    std::snprintf(gaps, sizeof(gaps), "; median singular-value gap %.4f -> %.4f, sharpness %.3f",
                  entry.median_gap_prior, entry.median_gap_estimated, entry.sharpness);
    Info(line + (entry.estimated_focal > 0.0 ? gaps : ""));
  }
  if (report.num_pairs_undefined > 0) {
    Info("focal calibration: " + std::to_string(report.num_pairs_undefined) + " of " +
         std::to_string(report.num_pairs_given) +
         " pairs left out (fundamental matrix not defined: planar scene or rotation only)");
  }
}

nlohmann::json CalibrationJson(const sfm_pruning::FocalCalibrationReport& report) {
  nlohmann::json cameras = nlohmann::json::array();
  for (const sfm_pruning::IntrinsicFocalCalibration& entry : report.intrinsics) {
    cameras.push_back({{"intrinsic_id", entry.intrinsic_id},
                       {"prior_focal", entry.prior_focal},
                       {"estimated_focal", entry.estimated_focal},
                       {"accepted", entry.accepted},
                       {"reason", entry.reason},
                       {"pairs", entry.num_pairs},
                       {"median_gap_prior", entry.median_gap_prior},
                       {"median_gap_estimated", entry.median_gap_estimated},
                       {"sharpness", entry.sharpness}});
  }
  return {{"pairs_given", report.num_pairs_given},
          {"pairs_used", report.num_pairs_used},
          {"pairs_undefined", report.num_pairs_undefined},
          {"cameras", std::move(cameras)}};
}

std::set<sfm_pruning::IndexT> UncalibratedFocals(const sfm_pruning::FocalCalibrationReport& report,
                                                 const sfm_pruning::SfmData& scene) {
  std::set<sfm_pruning::IndexT> uncalibrated;
  for (const sfm_pruning::IntrinsicFocalCalibration& entry : report.intrinsics) {
    if (!entry.accepted && sfm_pruning::IsPinholeFamily(scene.intrinsics.at(entry.intrinsic_id).model())) {
      uncalibrated.insert(entry.intrinsic_id);
    }
  }
  return uncalibrated;
}

std::string MovedFocals(const sfm_pruning::SfmData& before, const sfm_pruning::SfmData& after,
                        const std::set<sfm_pruning::IndexT>& refined, double threshold) {
  std::string moved;
  for (const sfm_pruning::IndexT id : refined) {
    const double old_focal = before.intrinsics.at(id).FocalLength();
    const double new_focal = after.intrinsics.at(id).FocalLength();
    if (std::abs(new_focal - old_focal) <= threshold * old_focal) continue;
    moved += (moved.empty() ? "" : ", ") + std::string("camera ") + std::to_string(id) + ": " + Pixels(old_focal) +
             " -> " + Pixels(new_focal);
  }
  return moved;
}

}  // namespace prunesfm
