#include "sfm_pruning/global/distortion_evidence.hpp"

#include <cmath>
#include <set>
#include <utility>

#include "sfm_pruning/sfm/camera_models.hpp"

namespace sfm_pruning {

size_t NumFreeDistortionParameters(const BundleAdjustmentOptions& options, const SfmData& sfm_data) {
  if (!options.refine_distortion) return 0;
  std::set<IndexT> used;
  for (const IndexT view_id : sfm_data.PosedViewIds()) used.insert(sfm_data.views.at(view_id).id_intrinsic);
  size_t count = 0;
  for (const IndexT id : used) {
    if (options.constant_intrinsics.count(id) > 0) continue;
    const CameraModel model = sfm_data.intrinsics.at(id).model();
    if (!IsPinholeFamily(model) || model == CameraModel::kPinholeFxFy) continue;
    const size_t num_params = NumCameraParams(model);
    if (num_params > static_cast<size_t>(camera_models::kFirstDistortionParam)) {
      count += num_params - static_cast<size_t>(camera_models::kFirstDistortionParam);
    }
  }
  return count;
}

DistortionEvidence SelectDistortionByEvidence(const BundleAdjustmentOptions& options, SfmData* sfm_data) {
  DistortionEvidence evidence;
  evidence.num_parameters = NumFreeDistortionParameters(options, *sfm_data);
  if (evidence.num_parameters == 0) return evidence;
  SfmData held = *sfm_data;
  evidence.adjustment = AdjustBundle(options, sfm_data);
  const BundleAdjustmentResult& free = evidence.adjustment;
  if (!free.success || free.num_observations == 0 || !(free.initial_rms_px > 0.0)) {
    *sfm_data = std::move(held);
    return evidence;
  }
  evidence.tested = true;
  evidence.num_residuals = 2 * free.num_observations;
  // Ceres' cost is half the sum of the robustified squared residuals: twice the saving is in px^2,
  // comparable with the residual variance (the Huber loss is quadratic below its 1 px scale).
  const double variance = free.initial_rms_px * free.initial_rms_px;
  evidence.statistic = 2.0 * (free.initial_cost - free.final_cost) / variance;
  evidence.threshold =
      static_cast<double>(evidence.num_parameters) * std::log(static_cast<double>(evidence.num_residuals));
  evidence.kept = evidence.statistic > evidence.threshold;
  if (!evidence.kept) *sfm_data = std::move(held);
  return evidence;
}

}  // namespace sfm_pruning
