// Intrinsics estimation of `prunesfm reconstruct` and `prunesfm run`: which cameras
// (--refine_intrinsics) and which parameters (--refine_focal, --refine_distortion,
// --refine_principal_point), the view-graph focal calibration that runs before verification, and
// the bundle-adjustment settings that follow from them.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "sfm_pruning/global/focal_calibration.hpp"
#include "sfm_pruning/pipeline/intrinsics_refinement.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

// The flags of sfm_pruning::IntrinsicsRefinementOptions (pipeline/intrinsics_refinement.hpp says
// what each does), the camera selection by its name.
struct IntrinsicsSettings {
  std::string cameras = "AUTO";  // AUTO, GUESSED, ALL or NONE
  bool focal = true;
  bool distortion = true;
  bool distortion_needs_evidence = true;
  bool principal_point = true;
  double refocus_threshold = 0.05;
};

// Adds --refine_intrinsics, --refine_focal, --refine_distortion, --distortion_needs_evidence,
// --refine_principal_point.
void AddIntrinsicsOptions(CLI::App* cmd, IntrinsicsSettings* settings);

// The library's options (pipeline/intrinsics_refinement.hpp) for the settings the flags filled.
sfm_pruning::IntrinsicsRefinementOptions ToIntrinsicsOptions(const IntrinsicsSettings& settings);

// The calibration's record in timings.json.
nlohmann::json CalibrationJson(const sfm_pruning::FocalCalibrationReport& report);

}  // namespace prunesfm
