// Which camera intrinsics a reconstruction estimates, and how: the cameras (all but the
// calibrated ones, only those with a guessed focal, all, none), their parameters, the view-graph
// focal calibration before verification, the bundle-adjustment settings that follow, and the
// rule that verifies and solves again when bundle adjustment moves a focal.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/global/focal_calibration.hpp"
#include "sfm_pruning/pipeline/reconstruction_input.hpp"

namespace sfm_pruning {

struct IntrinsicsRefinementOptions {
  // Cameras whose intrinsics are estimated:
  //   kAuto (default): every camera but the calibrated ones (a K file). A camera whose focal is a
  //     guess (COLMAP's prior_focal_length = 0, no EXIF) gets the whole treatment below; a camera
  //     with a focal prior (EXIF) keeps its principal point and skips the view-graph calibration,
  //     but its focal and distortion are refined in bundle adjustment, as COLMAP does: an EXIF
  //     focal is rounded and says nothing of the lens distortion (books: k1 = -0.046 left out
  //     costs 2-5 degrees on every pair).
  //   kGuessed: only the cameras with a guessed focal; kAll: every camera, the whole treatment;
  //   kNone.
  enum class Cameras { kAuto, kGuessed, kAll, kNone };
  Cameras cameras = Cameras::kAuto;
  // Which of their parameters. The focal is first calibrated on the view graph (fundamental
  // matrices), then every parameter chosen is refined in bundle adjustment. A guessed camera's
  // principal point is a guess too (the image centre), hence refined by default.
  bool focal = true;
  bool distortion = true;
  // The refined distortion is kept only when the data determine it (GlobalEngineOptions::
  // distortion_needs_evidence, global/distortion_evidence.hpp).
  bool distortion_needs_evidence = true;
  bool principal_point = true;
  // When bundle adjustment moves a refined focal by more than this fraction of the focal the
  // pairs were verified with, verification and engine run once more with the refined intrinsics.
  double refocus_threshold = 0.05;

  // Throws std::invalid_argument naming the field when a value is out of range.
  void Check() const;
};

// "AUTO", "GUESSED", "ALL", "NONE" and back; ParseIntrinsicsCameras throws std::invalid_argument
// on any other name.
std::string IntrinsicsCamerasName(IntrinsicsRefinementOptions::Cameras cameras);
IntrinsicsRefinementOptions::Cameras ParseIntrinsicsCameras(const std::string& name);

// The intrinsic ids whose parameters are estimated.
std::set<IndexT> RefinedIntrinsics(const IntrinsicsRefinementOptions& options,
                                   const ReconstructionInput& input);

// Those of them whose focal is calibrated on the view graph before verification (kAuto: the ones
// with a guessed focal; kGuessed and kAll: all of them).
std::set<IndexT> FocalsToCalibrate(const IntrinsicsRefinementOptions& options,
                                   const ReconstructionInput& input);

// Bundle adjustment settings: the chosen parameters of the refined cameras, every other camera
// held.
BundleAdjustmentOptions RefiningBundleOptions(const IntrinsicsRefinementOptions& options,
                                              const ReconstructionInput& input,
                                              const std::set<IndexT>& refined);

// One line per calibrated camera (and one for the pairs left out), for a log.
std::vector<std::string> CalibrationLines(const FocalCalibrationReport& report);

// The cameras of `report` whose focal the pairs could not determine (pinhole-family cameras the
// calibration rejected): the reconstruction searches their focal with a quick solve first.
std::set<IndexT> UncalibratedFocals(const FocalCalibrationReport& report, const SfmData& scene);

// "camera 1: 768.0 px -> 1537.5 px, ..." for the refined cameras whose focal moved by more than
// `threshold` (relative) between `before` and `after`; empty when none did.
std::string MovedFocals(const SfmData& before, const SfmData& after, const std::set<IndexT>& refined,
                        double threshold);

}  // namespace sfm_pruning
