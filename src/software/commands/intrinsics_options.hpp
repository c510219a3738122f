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
  // Cameras whose intrinsics are estimated:
  //   AUTO (default): every camera but the calibrated ones (a K file). A camera whose focal is a
  //     guess (COLMAP's prior_focal_length = 0, no EXIF) gets the whole treatment below; a camera
  //     with a focal prior (EXIF) keeps its principal point and skips the view-graph calibration,
  //     but its focal and distortion are refined in bundle adjustment, as COLMAP does: an EXIF
  //     focal is rounded and says nothing of the lens distortion (books: k1 = −0.046 left out
  //     costs 2–5° on every pair).
  //   GUESSED: only the cameras with a guessed focal; ALL: every camera, the whole treatment;
  //   NONE.
  std::string cameras = "AUTO";
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

// Those of them whose focal is calibrated on the view graph before verification (AUTO: the ones
// with a guessed focal; GUESSED and ALL: all of them).
std::set<sfm_pruning::IndexT> FocalsToCalibrate(const IntrinsicsSettings& settings,
                                                    const ReconstructionInput& input);

// Bundle adjustment settings: the chosen parameters of the refined cameras, every other camera
// held.
sfm_pruning::BundleAdjustmentOptions RefiningBundleOptions(const IntrinsicsSettings& settings,
                                                           const ReconstructionInput& input,
                                                           const std::set<sfm_pruning::IndexT>& refined);

// One progress line per calibrated camera (and one for the pairs left out).
void ReportCalibration(const sfm_pruning::FocalCalibrationReport& report);
nlohmann::json CalibrationJson(const sfm_pruning::FocalCalibrationReport& report);

// The cameras of `report` whose focal the pairs could not determine (pinhole-family cameras the
// calibration rejected): the reconstruction searches their focal with a quick solve first.
std::set<sfm_pruning::IndexT> UncalibratedFocals(const sfm_pruning::FocalCalibrationReport& report,
                                                 const sfm_pruning::SfmData& scene);

// "camera 1: 768.0 px -> 1537.5 px, ..." for the refined cameras whose focal moved by more than
// `threshold` (relative) between `before` and `after`; empty when none did.
std::string MovedFocals(const sfm_pruning::SfmData& before, const sfm_pruning::SfmData& after,
                        const std::set<sfm_pruning::IndexT>& refined, double threshold);

}  // namespace prunesfm
