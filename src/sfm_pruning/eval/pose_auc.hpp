// Area under the recall-versus-error curve (AUC), as GLOMAP and the PruneSfM paper report
// pairwise pose accuracy (the same integration as the SuperGlue/LightGlue `pose_auc`).
//
// Exact formula. Sort the N errors (failures are +infinity and stay in N):
//   e_1 <= e_2 <= ... <= e_N,   recall r_k = k / N,   and prepend (e_0, r_0) = (0, 0).
// Let m = the number of errors strictly below the threshold t. Then
//   AUC(t) = 100 / t * [ sum_{k=1..m} (e_k - e_{k-1}) * (r_{k-1} + r_k) / 2     (trapezoids)
//                        + (t - e_m) * r_m ]                                      (last piece)
// i.e. the curve is piecewise linear between consecutive errors and, after the last error
// below t, stays at r_m up to t (the next point lies beyond t and is not interpolated).
// Holding the last piece flat is what the reference implementations do; on the COLMAP temple
// models of ../shared/formats/colmap it reproduces the published numbers, the interpolated
// variant differs by up to 0.05.
// AUC = 100 when every error is 0; an error equal to t counts as above t.
#pragma once

#include <vector>

namespace sfm_pruning {

// AUC(t) in percent for one threshold (same unit as the errors, > 0). Errors are >= 0;
// +infinity marks a failure. An empty list gives 0. Throws Error for t <= 0 or a negative or
// NaN error.
double AucPercent(const std::vector<double>& errors, double threshold);

// AUC for several thresholds, sorting the errors once. Result i belongs to thresholds[i].
std::vector<double> AucPercent(const std::vector<double>& errors, const std::vector<double>& thresholds);

}  // namespace sfm_pruning
