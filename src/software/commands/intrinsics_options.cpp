#include "software/commands/intrinsics_options.hpp"

#include <CLI/CLI.hpp>

#include "software/help_format.hpp"

namespace prunesfm {

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
      ->add_option("--distortion_needs_evidence", settings->distortion_needs_evidence,
                   "With --refine_distortion: adjust with the distortion held, then keep a last adjustment with it\n"
                   "free only when the cost it saves pays the Bayesian information criterion's price k ln(n) (free\n"
                   "coefficients can bend a ring or a walk at no cost; docs/global.md). false: refine it throughout")
      ->capture_default_str();
  group
      ->add_option("--refine_principal_point", settings->principal_point,
                   "For those cameras: refine the principal point in bundle adjustment")
      ->capture_default_str();
  // Which cameras to calibrate is the common choice; what to refine of them is for --help_all.
  MarkExpertExcept(group, "--refine_intrinsics");
}

sfm_pruning::IntrinsicsRefinementOptions ToIntrinsicsOptions(const IntrinsicsSettings& settings) {
  sfm_pruning::IntrinsicsRefinementOptions options;
  options.cameras = sfm_pruning::ParseIntrinsicsCameras(settings.cameras);
  options.focal = settings.focal;
  options.distortion = settings.distortion;
  options.distortion_needs_evidence = settings.distortion_needs_evidence;
  options.principal_point = settings.principal_point;
  options.refocus_threshold = settings.refocus_threshold;
  return options;
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

}  // namespace prunesfm
