// Whether the data determine the lens distortion: a model selection (the Bayesian information
// criterion) between the adjusted model with its distortion held and the same model with it free.
//
// Why: free distortion coefficients can trade against the geometry. On a ring of views or a
// walk, a k1 of a few hundredths bends the whole model, and the reprojection cost hardly changes:
// on generated scenes without any distortion (the scene families, the true edges only) refining
// it cost 2-17 AUC@10 points on courtyards and streets with the same or a higher cost at the end.
// Real lenses (books: k1 = -0.046) lower the cost by far more than the criterion asks.
//
// How: the engine adjusts and filters with the distortion held; then one more adjustment frees
// it, starting from that solution, on the same observations. The cost it saves (twice the
// difference of the robust costs, in px^2, over the held solution's residual variance) is compared
// with BIC's price for its parameters, k ln(n) (k free coefficients, n residual coordinates). Only
// when it pays for itself does the engine estimate the distortion, and then from the positioned
// model on (global_engine.cpp): held through the filtering rounds, a real distortion makes the
// filter drop the observations near the image border (the real street lost 22 AUC@5 points).
#pragma once

#include <cstddef>

#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct DistortionEvidence {
  bool tested = false;         // an adjustment with free distortion ran
  bool kept = false;           // its solution was kept
  size_t num_parameters = 0;   // free distortion coefficients (k)
  size_t num_residuals = 0;    // residual coordinates (n)
  double statistic = 0.0;      // 2 (cost held - cost free) / variance of the held residuals
  double threshold = 0.0;      // k ln(n)
  BundleAdjustmentResult adjustment;  // the adjustment with free distortion
};

// Free distortion coefficients of the cameras `options` refines (refine_distortion, minus the
// constant intrinsics) that a posed view of `sfm_data` uses.
size_t NumFreeDistortionParameters(const BundleAdjustmentOptions& options, const SfmData& sfm_data);

// Runs the adjustment with `options` (distortion free) from `sfm_data` as it is (adjusted with the
// distortion held) and keeps its solution only when the statistic exceeds the threshold;
// otherwise `sfm_data` is left as it was. Nothing is tested (tested = false) when no free
// coefficient is in play or the adjustment fails.
DistortionEvidence SelectDistortionByEvidence(const BundleAdjustmentOptions& options, SfmData* sfm_data);

}  // namespace sfm_pruning
