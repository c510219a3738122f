#include "sfm_pruning/global/focal_calibration.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <ceres/ceres.h>
#include <Eigen/SVD>

#include "sfm_pruning/geometry/fundamental_matrix.hpp"

namespace sfm_pruning {
namespace {

// One usable pair: its F in the prior's normalised coordinates and which intrinsics it uses.
struct PairModel {
  IndexT intrinsic_i = kUndefinedIndex;
  IndexT intrinsic_j = kUndefinedIndex;
  Eigen::Matrix3d F_normalized;
};

// log(focal / prior focal) of each calibrated intrinsic; absent = held at the prior.
using LogRatios = std::map<IndexT, double>;

double SingularValueGap(const Eigen::Matrix3d& F_normalized, double lambda_i, double lambda_j) {
  Eigen::Matrix3d E = F_normalized;
  E.topRows<2>() *= lambda_j;
  E.leftCols<2>() *= lambda_i;
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(E).singularValues();
  const double sum = s(0) + s(1);
  return sum > 0.0 ? (s(0) - s(1)) / sum : 1.0;
}

double Ratio(const LogRatios& ratios, IndexT intrinsic_id) {
  const auto it = ratios.find(intrinsic_id);
  return it == ratios.end() ? 1.0 : std::exp(it->second);
}

double PairGap(const PairModel& pair, const LogRatios& ratios) {
  return SingularValueGap(pair.F_normalized, Ratio(ratios, pair.intrinsic_i), Ratio(ratios, pair.intrinsic_j));
}

// The Cauchy-robustified cost the solver minimises (Ceres' 0.5 factor left out).
double RobustCost(double gap, double scale) { return scale * scale * std::log1p(gap * gap / (scale * scale)); }

bool Involves(const PairModel& pair, IndexT intrinsic_id) {
  return pair.intrinsic_i == intrinsic_id || pair.intrinsic_j == intrinsic_id;
}

// Sum of robust costs over the pairs that involve `intrinsic_id` (every pair when undefined).
double TotalCost(const std::vector<PairModel>& pairs, const LogRatios& ratios, double scale,
                 IndexT intrinsic_id = kUndefinedIndex) {
  double total = 0.0;
  for (const PairModel& pair : pairs) {
    if (intrinsic_id == kUndefinedIndex || Involves(pair, intrinsic_id)) total += RobustCost(PairGap(pair, ratios), scale);
  }
  return total;
}

double MedianGap(const std::vector<PairModel>& pairs, const LogRatios& ratios, IndexT intrinsic_id) {
  std::vector<double> gaps;
  for (const PairModel& pair : pairs) {
    if (Involves(pair, intrinsic_id)) gaps.push_back(PairGap(pair, ratios));
  }
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

// Residual g of one pair; parameter block k is the log ratio of the k-th calibrated intrinsic
// the pair involves (slot -1: that side is held at the prior).
class GapResidual {
 public:
  GapResidual(const Eigen::Matrix3d& F_normalized, int slot_i, int slot_j)
      : F_normalized_(F_normalized), slot_i_(slot_i), slot_j_(slot_j) {}
  bool operator()(double const* const* parameters, double* residual) const {
    const double lambda_i = slot_i_ < 0 ? 1.0 : std::exp(parameters[slot_i_][0]);
    const double lambda_j = slot_j_ < 0 ? 1.0 : std::exp(parameters[slot_j_][0]);
    residual[0] = SingularValueGap(F_normalized_, lambda_i, lambda_j);
    return true;
  }

 private:
  Eigen::Matrix3d F_normalized_;
  int slot_i_;
  int slot_j_;
};

// Fits each usable pair; counts the undefined ones in the report.
std::vector<PairModel> FitPairs(const FocalCalibrationOptions& options, const std::set<IndexT>& calibrate,
                                const PairInliers& pairs, const FeaturesPerView& features, const SfmData& scene,
                                FocalCalibrationReport* report) {
  std::vector<PairModel> models;
  for (const auto& [pair, matches] : pairs) {
    const auto view_i = scene.views.find(pair.first);
    const auto view_j = scene.views.find(pair.second);
    if (view_i == scene.views.end() || view_j == scene.views.end()) continue;
    const IndexT intrinsic_i = view_i->second.id_intrinsic;
    const IndexT intrinsic_j = view_j->second.id_intrinsic;
    if (calibrate.count(intrinsic_i) == 0 && calibrate.count(intrinsic_j) == 0) continue;
    const auto camera_i = scene.intrinsics.find(intrinsic_i);
    const auto camera_j = scene.intrinsics.find(intrinsic_j);
    const auto features_i = features.find(pair.first);
    const auto features_j = features.find(pair.second);
    if (camera_i == scene.intrinsics.end() || camera_j == scene.intrinsics.end() || features_i == features.end() ||
        features_j == features.end() || !IsPinholeFamily(camera_i->second.model()) ||
        !IsPinholeFamily(camera_j->second.model()) || matches->size() < options.min_inliers_per_pair) {
      continue;
    }
    std::vector<Eigen::Vector2d> points_i, points_j;
    points_i.reserve(matches->size());
    points_j.reserve(matches->size());
    for (const FeatureMatch& match : *matches) {
      if (match.i >= features_i->second.size() || match.j >= features_j->second.size()) continue;
      points_i.push_back(camera_i->second.PixelToNormalized(features_i->second.Position(match.i)));
      points_j.push_back(camera_j->second.PixelToNormalized(features_j->second.Position(match.j)));
    }
    FundamentalMatrixOptions fit;
    fit.robust_scale =
        options.sampson_scale_px * 2.0 / (camera_i->second.FocalLength() + camera_j->second.FocalLength());
    PairModel model;
    model.intrinsic_i = intrinsic_i;
    model.intrinsic_j = intrinsic_j;
    double definition = 0.0;
    const bool ok = EstimateFundamentalMatrix(points_i, points_j, fit, &model.F_normalized, &definition);
    if (!ok || definition < options.min_f_definition) {
      ++report->num_pairs_undefined;
      continue;
    }
    models.push_back(model);
  }
  return models;
}

// The shared log ratio of the grid with the lowest total cost.
double GridSearch(const FocalCalibrationOptions& options, const std::vector<PairModel>& pairs,
                  const std::set<IndexT>& active) {
  const double low = std::log(options.min_focal_ratio);
  const double high = std::log(options.max_focal_ratio);
  const int steps = std::max(options.num_grid_steps, 2);
  double best = 0.0;
  double best_cost = TotalCost(pairs, {}, options.gap_loss_scale);
  for (int k = 0; k < steps; ++k) {
    const double value = low + (high - low) * k / (steps - 1);
    LogRatios ratios;
    for (const IndexT id : active) ratios[id] = value;
    const double cost = TotalCost(pairs, ratios, options.gap_loss_scale);
    if (cost < best_cost) {
      best_cost = cost;
      best = value;
    }
  }
  return best;
}

// Refines the log ratios of `active` (started at `ratios`) with Ceres.
void Refine(const FocalCalibrationOptions& options, const std::vector<PairModel>& pairs, LogRatios* ratios) {
  ceres::Problem problem;
  for (const PairModel& pair : pairs) {
    std::vector<double*> blocks;
    const auto slot = [&](IndexT id) -> int {
      const auto it = ratios->find(id);
      if (it == ratios->end()) return -1;
      for (size_t k = 0; k < blocks.size(); ++k) {
        if (blocks[k] == &it->second) return static_cast<int>(k);
      }
      blocks.push_back(&it->second);
      return static_cast<int>(blocks.size() - 1);
    };
    const int slot_i = slot(pair.intrinsic_i);
    const int slot_j = slot(pair.intrinsic_j);
    if (blocks.empty()) continue;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<GapResidual, ceres::CENTRAL>(
        new GapResidual(pair.F_normalized, slot_i, slot_j));
    for (size_t k = 0; k < blocks.size(); ++k) cost->AddParameterBlock(1);
    cost->SetNumResiduals(1);
    problem.AddResidualBlock(cost, new ceres::CauchyLoss(options.gap_loss_scale), blocks);
  }
  for (auto& [id, value] : *ratios) {
    if (!problem.HasParameterBlock(&value)) continue;
    problem.SetParameterLowerBound(&value, 0, std::log(options.min_focal_ratio));
    problem.SetParameterUpperBound(&value, 0, std::log(options.max_focal_ratio));
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = 100;
  solver.function_tolerance = 1e-10;
  solver.parameter_tolerance = 1e-10;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
}

}  // namespace

PairInliers InliersOfPairs(const VerifiedPairs& verified) {
  PairInliers inliers;
  for (const auto& [pair, entry] : verified) inliers.emplace(pair, &entry.inliers);
  return inliers;
}

PairInliers InliersOfEdges(const ViewGraph& graph) {
  PairInliers inliers;
  for (const auto& [pair, edge] : graph.Edges()) {
    if (edge.is_valid) inliers.emplace(pair, &edge.matches);
  }
  return inliers;
}

FocalCalibrationReport CalibrateFocalLengths(const FocalCalibrationOptions& options, const std::set<IndexT>& calibrate,
                                             const PairInliers& pairs, const FeaturesPerView& features,
                                             SfmData* scene) {
  options.Check();
  FocalCalibrationReport report;
  report.num_pairs_given = pairs.size();
  const std::vector<PairModel> models = FitPairs(options, calibrate, pairs, features, *scene, &report);
  report.num_pairs_used = models.size();

  // Intrinsics with enough pairs take part; the others stay at the prior.
  std::set<IndexT> active;
  for (const IndexT id : calibrate) {
    const auto camera = scene->intrinsics.find(id);
    if (camera == scene->intrinsics.end()) continue;
    IntrinsicFocalCalibration entry;
    entry.intrinsic_id = id;
    entry.prior_focal = camera->second.FocalLength();
    entry.num_pairs = static_cast<size_t>(
        std::count_if(models.begin(), models.end(), [&](const PairModel& pair) { return Involves(pair, id); }));
    if (!IsPinholeFamily(camera->second.model())) {
      entry.reason = "not a pinhole camera";
    } else if (entry.num_pairs < options.min_pairs_per_intrinsic) {
      entry.reason = "too few pairs with a defined fundamental matrix (" + std::to_string(entry.num_pairs) + " < " +
                     std::to_string(options.min_pairs_per_intrinsic) + ")";
    } else {
      active.insert(id);
    }
    report.intrinsics.push_back(entry);
  }
  if (active.empty()) return report;

  LogRatios ratios;
  const double start = GridSearch(options, models, active);
  for (const IndexT id : active) ratios[id] = start;
  Refine(options, models, &ratios);

  const double low = std::log(options.min_focal_ratio);
  const double high = std::log(options.max_focal_ratio);
  const double margin = 0.01 * (high - low);
  for (IntrinsicFocalCalibration& entry : report.intrinsics) {
    if (active.count(entry.intrinsic_id) == 0) continue;
    const double value = ratios.at(entry.intrinsic_id);
    entry.estimated_focal = entry.prior_focal * std::exp(value);
    entry.median_gap_prior = MedianGap(models, {}, entry.intrinsic_id);
    entry.median_gap_estimated = MedianGap(models, ratios, entry.intrinsic_id);
    const double scale = options.gap_loss_scale;
    const double cost = TotalCost(models, ratios, scale, entry.intrinsic_id);
    double neighbour_cost = std::numeric_limits<double>::infinity();
    for (const double step : {std::log1p(options.sharpness_step), -std::log1p(options.sharpness_step)}) {
      LogRatios moved = ratios;
      moved[entry.intrinsic_id] = value + step;
      neighbour_cost = std::min(neighbour_cost, TotalCost(models, moved, scale, entry.intrinsic_id));
    }
    entry.sharpness = cost > 0.0 ? (neighbour_cost - cost) / cost : std::numeric_limits<double>::infinity();
    if (value < low + margin || value > high - margin) {
      entry.reason = "estimate at the end of the search range";
    } else if (TotalCost(models, {}, scale, entry.intrinsic_id) < cost) {
      entry.reason = "the estimate fits the pairs worse than the prior";
    } else if (entry.sharpness < options.min_sharpness) {
      entry.reason = "the pairs do not determine the focal (flat cost)";
    } else {
      entry.accepted = true;
    }
  }
  // Write the accepted focals; rejected intrinsics keep the prior.
  for (const IntrinsicFocalCalibration& entry : report.intrinsics) {
    if (!entry.accepted) continue;
    CameraIntrinsics& camera = scene->intrinsics.at(entry.intrinsic_id);
    const double ratio = entry.estimated_focal / entry.prior_focal;
    std::vector<double>& params = camera.mutable_params();
    params[0] *= ratio;
    if (camera.model() == CameraModel::kPinholeFxFy) params[1] *= ratio;
  }
  return report;
}

void FocalCalibrationOptions::Check() const {
  // The range is searched in log(focal / prior): both ends positive and finite, in increasing order.
  RequirePositiveAtMost(min_focal_ratio, 1e6, "FocalCalibrationOptions::min_focal_ratio");
  RequirePositiveAtMost(max_focal_ratio, 1e6, "FocalCalibrationOptions::max_focal_ratio");
  if (!(max_focal_ratio > min_focal_ratio)) {
    throw std::invalid_argument("FocalCalibrationOptions::max_focal_ratio must exceed min_focal_ratio");
  }
  // The grid's two ends at least.
  RequireAtLeast(num_grid_steps, 2, "FocalCalibrationOptions::num_grid_steps");
  RequirePositiveAtMost(gap_loss_scale, 1e6, "FocalCalibrationOptions::gap_loss_scale");
  RequireAtLeast(min_f_definition, 0.0, "FocalCalibrationOptions::min_f_definition");
  RequirePositiveAtMost(sampson_scale_px, 1e6, "FocalCalibrationOptions::sampson_scale_px");
  // An intrinsic without a pair would take the grid's start as its focal.
  RequireAtLeast<size_t>(min_pairs_per_intrinsic, 1, "FocalCalibrationOptions::min_pairs_per_intrinsic");
  RequirePositiveAtMost(sharpness_step, 1e6, "FocalCalibrationOptions::sharpness_step");
  RequireAtLeast(min_sharpness, 0.0, "FocalCalibrationOptions::min_sharpness");
}

}  // namespace sfm_pruning
