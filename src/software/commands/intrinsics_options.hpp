// Intrinsics estimation of `prunesfm reconstruct` and `prunesfm run`: which cameras
// (--refine_intrinsics) and which parameters (--refine_focal, --refine_distortion,
// --refine_principal_point), the view-graph focal calibration that runs before verification, and
// the bundle-adjustment settings that follow from them.
#pragma once

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/global/focal_calibration.hpp"
#include "software/commands/reconstruction_input.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

struct IntrinsicsSettings {
  // Cameras whose intrinsics are estimated: GUESSED (the focal is a guess: a COLMAP camera with
  // prior_focal_length = 0), ALL or NONE.
  std::string cameras = "GUESSED";
  // Which of their parameters. The focal is first calibrated on the view graph (fundamental
  // matrices), then every parameter chosen is refined in bundle adjustment. A guessed camera's
  // principal point is a guess too (the image centre), hence refined by default.
  bool focal = true;
  bool distortion = true;
  bool principal_point = true;
  // When bundle adjustment moves a refined focal by more than this fraction of the focal the
  // pairs were verified with, verification and engine run once more with the refined intrinsics.
  double refocus_threshold = 0.05;
};

// Adds --refine_intrinsics, --refine_focal, --refine_distortion, --refine_principal_point.
void AddIntrinsicsOptions(CLI::App* cmd, IntrinsicsSettings* settings);

// The intrinsic ids whose parameters are estimated.
std::set<sfm_pruning::IndexT> RefinedIntrinsics(const IntrinsicsSettings& settings, const ReconstructionInput& input);

// Bundle adjustment settings: the chosen parameters of the refined cameras, every other camera
// held.
sfm_pruning::BundleAdjustmentOptions RefiningBundleOptions(const IntrinsicsSettings& settings,
                                                           const sfm_pruning::SfmData& scene,
                                                           const std::set<sfm_pruning::IndexT>& refined);

// One progress line per calibrated camera (and one for the pairs left out).
void ReportCalibration(const sfm_pruning::FocalCalibrationReport& report);
nlohmann::json CalibrationJson(const sfm_pruning::FocalCalibrationReport& report);

// "camera 1: 768.0 px -> 1537.5 px, ..." for the refined cameras whose focal moved by more than
// `threshold` (relative) between `before` and `after`; empty when none did.
std::string MovedFocals(const sfm_pruning::SfmData& before, const sfm_pruning::SfmData& after,
                        const std::set<sfm_pruning::IndexT>& refined, double threshold);

}  // namespace prunesfm
