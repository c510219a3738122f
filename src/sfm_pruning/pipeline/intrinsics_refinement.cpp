#include "sfm_pruning/pipeline/intrinsics_refinement.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sfm_pruning {
namespace {

std::string Pixels(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f px", value);
  return text;
}

}  // namespace

void IntrinsicsRefinementOptions::Check() const {
  if (!(refocus_threshold > 0.0 && std::isfinite(refocus_threshold))) {
    throw std::invalid_argument("IntrinsicsRefinementOptions::refocus_threshold must be positive and finite");
  }
}

std::string IntrinsicsCamerasName(IntrinsicsRefinementOptions::Cameras cameras) {
  switch (cameras) {
    case IntrinsicsRefinementOptions::Cameras::kAuto:
      return "AUTO";
    case IntrinsicsRefinementOptions::Cameras::kGuessed:
      return "GUESSED";
    case IntrinsicsRefinementOptions::Cameras::kAll:
      return "ALL";
    case IntrinsicsRefinementOptions::Cameras::kNone:
      return "NONE";
  }
  return "AUTO";
}

IntrinsicsRefinementOptions::Cameras ParseIntrinsicsCameras(const std::string& name) {
  for (const auto cameras :
       {IntrinsicsRefinementOptions::Cameras::kAuto, IntrinsicsRefinementOptions::Cameras::kGuessed,
        IntrinsicsRefinementOptions::Cameras::kAll, IntrinsicsRefinementOptions::Cameras::kNone}) {
    if (IntrinsicsCamerasName(cameras) == name) return cameras;
  }
  throw std::invalid_argument("unknown intrinsics camera selection '" + name +
                              "' (AUTO, GUESSED, ALL or NONE)");
}

std::set<IndexT> RefinedIntrinsics(const IntrinsicsRefinementOptions& options,
                                   const ReconstructionInput& input) {
  using Cameras = IntrinsicsRefinementOptions::Cameras;
  if (options.cameras == Cameras::kNone) return {};
  if (options.cameras == Cameras::kGuessed) return input.guessed_focal;
  std::set<IndexT> refined;
  for (const auto& [intrinsic_id, intrinsics] : input.scene.intrinsics) {
    if (options.cameras == Cameras::kAll || input.k_file_intrinsics.count(intrinsic_id) == 0) {
      refined.insert(intrinsic_id);
    }
  }
  return refined;
}

std::set<IndexT> FocalsToCalibrate(const IntrinsicsRefinementOptions& options,
                                   const ReconstructionInput& input) {
  std::set<IndexT> refined = RefinedIntrinsics(options, input);
  if (options.cameras != IntrinsicsRefinementOptions::Cameras::kAuto) return refined;
  std::set<IndexT> guessed;
  for (const IndexT id : refined) {
    if (input.guessed_focal.count(id) > 0) guessed.insert(id);
  }
  return guessed;
}

BundleAdjustmentOptions RefiningBundleOptions(const IntrinsicsRefinementOptions& options,
                                              const ReconstructionInput& input,
                                              const std::set<IndexT>& refined) {
  BundleAdjustmentOptions bundle;
  bundle.refine_focal = options.focal;
  bundle.refine_distortion = options.distortion;
  bundle.refine_principal_point = options.principal_point;
  for (const auto& [intrinsic_id, intrinsics] : input.scene.intrinsics) {
    if (refined.count(intrinsic_id) == 0) {
      bundle.constant_intrinsics.insert(intrinsic_id);
    } else if (options.cameras == IntrinsicsRefinementOptions::Cameras::kAuto &&
               input.guessed_focal.count(intrinsic_id) == 0) {
      bundle.constant_principal_point.insert(intrinsic_id);
    }
  }
  return bundle;
}

std::vector<std::string> CalibrationLines(const FocalCalibrationReport& report) {
  std::vector<std::string> lines;
  for (const IntrinsicFocalCalibration& entry : report.intrinsics) {
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
    lines.push_back(line + (entry.estimated_focal > 0.0 ? gaps : ""));
  }
  if (report.num_pairs_undefined > 0) {
    lines.push_back("focal calibration: " + std::to_string(report.num_pairs_undefined) + " of " +
                    std::to_string(report.num_pairs_given) +
                    " pairs left out (fundamental matrix not defined: planar scene or rotation only)");
  }
  return lines;
}

std::set<IndexT> UncalibratedFocals(const FocalCalibrationReport& report, const SfmData& scene) {
  std::set<IndexT> uncalibrated;
  for (const IntrinsicFocalCalibration& entry : report.intrinsics) {
    if (!entry.accepted && IsPinholeFamily(scene.intrinsics.at(entry.intrinsic_id).model())) {
      uncalibrated.insert(entry.intrinsic_id);
    }
  }
  return uncalibrated;
}

std::string MovedFocals(const SfmData& before, const SfmData& after, const std::set<IndexT>& refined,
                        double threshold) {
  std::string moved;
  for (const IndexT id : refined) {
    const double old_focal = before.intrinsics.at(id).FocalLength();
    const double new_focal = after.intrinsics.at(id).FocalLength();
    if (std::abs(new_focal - old_focal) <= threshold * old_focal) continue;
    moved += (moved.empty() ? "" : ", ") + std::string("camera ") + std::to_string(id) + ": " +
             Pixels(old_focal) + " -> " + Pixels(new_focal);
  }
  return moved;
}

}  // namespace sfm_pruning
