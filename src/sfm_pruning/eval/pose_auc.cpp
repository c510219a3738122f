#include "sfm_pruning/eval/pose_auc.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

double AucOfSortedPercent(const std::vector<double>& sorted, double threshold) {
  if (!(threshold > 0.0) || !std::isfinite(threshold)) {
    throw Error("AUC threshold must be a positive number, got " + std::to_string(threshold));
  }
  if (sorted.empty()) return 0.0;
  const double n = static_cast<double>(sorted.size());
  double area = 0.0;
  double previous_error = 0.0;
  double previous_recall = 0.0;
  for (size_t k = 0; k < sorted.size() && sorted[k] < threshold; ++k) {
    const double recall = static_cast<double>(k + 1) / n;
    area += (sorted[k] - previous_error) * (previous_recall + recall) / 2.0;
    previous_error = sorted[k];
    previous_recall = recall;
  }
  area += (threshold - previous_error) * previous_recall;
  return 100.0 * area / threshold;
}

}  // namespace

std::vector<double> AucPercent(const std::vector<double>& errors, const std::vector<double>& thresholds) {
  if (std::any_of(errors.begin(), errors.end(), [](double e) { return !(e >= 0.0); })) {
    throw Error("AUC: an error value is negative or NaN");
  }
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> aucs;
  aucs.reserve(thresholds.size());
  for (double threshold : thresholds) aucs.push_back(AucOfSortedPercent(sorted, threshold));
  return aucs;
}

double AucPercent(const std::vector<double>& errors, double threshold) {
  return AucPercent(errors, std::vector<double>{threshold}).front();
}

}  // namespace sfm_pruning
