#include "sfm_pruning/global/bundle_adjustment.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/normal_prior.h>

#include "sfm_pruning/global/bundle_observations.hpp"
#include "sfm_pruning/global/bundle_parameters.hpp"
#include "sfm_pruning/global/bundle_pose_manifold.hpp"
#include "sfm_pruning/global/bundle_reprojection_cost.hpp"

namespace sfm_pruning {
namespace {

// Where a pinhole-family model's parameter block (camera_models.hpp layouts) has its principal
// point (2 values) and its distortion coefficients (to the end; none for pinhole_fx_fy).
struct IntrinsicLayout {
  int num_params = 0;
  int first_principal = 1;
  int first_distortion = 0;
};

IntrinsicLayout LayoutOf(CameraModel model) {
  IntrinsicLayout layout;
  layout.num_params = static_cast<int>(NumCameraParams(model));
  const bool two_focals = model == CameraModel::kPinholeFxFy;
  layout.first_principal = two_focals ? 2 : 1;
  layout.first_distortion = two_focals ? layout.num_params : camera_models::kFirstDistortionParam;
  return layout;
}

// Indices of the intrinsic parameters held constant.
std::vector<int> ConstantIntrinsicParams(IndexT id, CameraModel model, const BundleAdjustmentOptions& options) {
  const IntrinsicLayout layout = LayoutOf(model);
  std::vector<int> constant;
  for (int k = 0; k < layout.num_params; ++k) {
    const bool refine = k < layout.first_principal       ? options.refine_focal
                        : k < layout.first_principal + 2 ? options.refine_principal_point &&
                                                               options.constant_principal_point.count(id) == 0
                        : k >= layout.first_distortion   ? options.refine_distortion
                                                         : false;
    if (!refine) constant.push_back(k);
  }
  return constant;
}

struct ErrorSummary {
  double rms_px = 0.0;
  size_t num_behind = 0;
};

// Unrobustified reprojection errors of the landmarks in the problem, as stored in `data`.
ErrorSummary MeasureErrors(const SfmData& data, const BundleParameters& parameters) {
  double sum_squared = 0.0;
  size_t num_finite = 0;
  ErrorSummary summary;
  for (size_t k = 0; k < parameters.landmark_ids().size(); ++k) {
    const Eigen::Vector3d& X = data.structure.at(parameters.landmark_ids()[k]).X;
    for (const PosedObservation& obs : parameters.observations(k)) {
      const double error = ReprojectionErrorPx(obs, X);
      if (!std::isfinite(error)) {
        ++summary.num_behind;
        continue;
      }
      sum_squared += error * error;
      ++num_finite;
    }
  }
  // Two coordinates per observation: the RMS is per coordinate.
  if (num_finite > 0) summary.rms_px = std::sqrt(sum_squared / (2.0 * static_cast<double>(num_finite)));
  return summary;
}

// Pose id of the smallest posed view id in the problem, kUndefinedIndex if none.
IndexT FirstPoseId(const SfmData& data, const BundleParameters& parameters) {
  for (const auto& [view_id, view] : data.views) {
    if (data.IsPosed(view) && parameters.pose_slots().count(view.id_pose)) return view.id_pose;
  }
  return kUndefinedIndex;
}

// The poses' manifolds, with the gauge of the header comment; returns the pose held constant
// (or kUndefinedIndex). Every pose is one block (quaternion, centre) on a PoseManifold, which on
// the scale gauge's pose holds one centre coordinate.
IndexT SetPoseManifoldsAndGauge(const BundleAdjustmentOptions& options, const SfmData& data,
                                BundleParameters* parameters, ceres::Problem* problem) {
  const IndexT first = options.fix_first_pose ? FirstPoseId(data, *parameters) : kUndefinedIndex;
  IndexT second = kUndefinedIndex;
  int axis = -1;
  if (first != kUndefinedIndex && options.fix_scale) {
    const Eigen::Map<const Eigen::Vector3d> first_center(parameters->center(first));
    double max_distance = 0.0;
    for (const auto& [pose_id, slot] : parameters->pose_slots()) {  // ties go to the smallest id
      const double distance = (Eigen::Map<const Eigen::Vector3d>(parameters->center(pose_id)) - first_center).norm();
      if (distance > max_distance) {
        max_distance = distance;
        second = pose_id;
      }
    }
    // All centres coincide: no scale to fix.
    if (second != kUndefinedIndex) {
      (Eigen::Map<const Eigen::Vector3d>(parameters->center(second)) - first_center).cwiseAbs().maxCoeff(&axis);
    }
  }
  for (const auto& [pose_id, slot] : parameters->pose_slots()) {
    problem->SetManifold(parameters->pose(pose_id), new bundle::PoseManifold(pose_id == second ? axis : -1));
  }
  if (first != kUndefinedIndex) problem->SetParameterBlockConstant(parameters->pose(first));
  return first;
}

void SetIntrinsicsManifolds(const BundleAdjustmentOptions& options, const SfmData& data,
                            BundleParameters* parameters, ceres::Problem* problem) {
  for (const auto& [id, offset] : parameters->intrinsic_offsets()) {
    const CameraIntrinsics& intrinsics = data.intrinsics.at(id);
    if (!IsPinholeFamily(intrinsics.model())) continue;  // no parameters, no block
    if (options.constant_intrinsics.count(id) > 0) {
      problem->SetParameterBlockConstant(parameters->intrinsics(id));
      continue;
    }
    const std::vector<int> constant = ConstantIntrinsicParams(id, intrinsics.model(), options);
    const int num_params = static_cast<int>(intrinsics.params().size());
    if (static_cast<int>(constant.size()) == num_params) {
      problem->SetParameterBlockConstant(parameters->intrinsics(id));
    } else if (!constant.empty()) {
      problem->SetManifold(parameters->intrinsics(id), new ceres::SubsetManifold(num_params, constant));
    }
  }
}

// The weak priors of BundleAdjustmentOptions on the refined principal points and distortion
// coefficients: one NormalPrior block per intrinsic, A (x - b) with A = diag(1 / sigma) over the
// parameters that have a prior.
void AddIntrinsicsPriors(const BundleAdjustmentOptions& options, const SfmData& data, BundleParameters* parameters,
                         ceres::Problem* problem) {
  for (const auto& [id, offset] : parameters->intrinsic_offsets()) {
    const CameraIntrinsics& intrinsics = data.intrinsics.at(id);
    if (!IsPinholeFamily(intrinsics.model()) || options.constant_intrinsics.count(id) > 0) continue;
    double* block = parameters->intrinsics(id);
    if (!problem->HasParameterBlock(block)) continue;
    const std::vector<int> constant = ConstantIntrinsicParams(id, intrinsics.model(), options);
    const IntrinsicLayout layout = LayoutOf(intrinsics.model());
    const double pp_sigma = options.principal_point_prior_sigma * std::max(intrinsics.width(), intrinsics.height());
    std::vector<std::pair<int, double>> rows;  // (parameter, 1 / sigma)
    for (int k = layout.first_principal; k < layout.num_params; ++k) {
      if (std::find(constant.begin(), constant.end(), k) != constant.end()) continue;
      const bool principal = k < layout.first_principal + 2;
      const double sigma = principal                        ? pp_sigma
                           : k >= layout.first_distortion ? options.distortion_prior_sigma
                                                           : 0.0;
      if (sigma > 0.0) rows.emplace_back(k, 1.0 / sigma);
    }
    if (rows.empty()) continue;
    ceres::Matrix A = ceres::Matrix::Zero(static_cast<Eigen::Index>(rows.size()), layout.num_params);
    ceres::Vector b = ceres::Vector::Zero(layout.num_params);  // distortion: 0
    b(layout.first_principal) = 0.5 * (intrinsics.width() - 1.0);  // the image centre (pixel-centre convention)
    b(layout.first_principal + 1) = 0.5 * (intrinsics.height() - 1.0);
    for (size_t r = 0; r < rows.size(); ++r) A(static_cast<Eigen::Index>(r), rows[r].first) = rows[r].second;
    problem->AddResidualBlock(new ceres::NormalPrior(A, b), nullptr, block);
  }
}

// One residual block per posed observation; returns the number of observations added.
size_t AddResiduals(const BundleAdjustmentOptions& options, const SfmData& data, BundleParameters* parameters,
                    ceres::Problem* problem) {
  // One loss object for every residual: the problem deletes it once.
  ceres::LossFunction* loss =
      options.huber_loss_scale_px > 0.0 ? new ceres::HuberLoss(options.huber_loss_scale_px) : nullptr;
  size_t num_observations = 0;
  for (size_t k = 0; k < parameters->landmark_ids().size(); ++k) {
    for (const PosedObservation& obs : parameters->observations(k)) {
      const CameraIntrinsics& intrinsics = *obs.intrinsics;
      const Eigen::Vector2d& pixel = obs.observation->x;
      double* pose = parameters->pose(obs.view->id_pose);
      if (IsPinholeFamily(intrinsics.model())) {
        problem->AddResidualBlock(bundle::CreatePinholeCost(intrinsics.model(), pixel), loss, pose,
                                  parameters->point(k), parameters->intrinsics(obs.view->id_intrinsic));
      } else {
        problem->AddResidualBlock(bundle::CreateSphericalCost(intrinsics, pixel), loss, pose, parameters->point(k));
      }
      ++num_observations;
    }
  }
  return num_observations;
}

// Landmarks first (group 0), then poses and intrinsics: the Schur complement eliminates the
// landmarks and solves the reduced camera system.
std::shared_ptr<ceres::ParameterBlockOrdering> EliminationOrdering(const ceres::Problem& problem,
                                                                   BundleParameters* parameters) {
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (size_t k = 0; k < parameters->landmark_ids().size(); ++k) ordering->AddElementToGroup(parameters->point(k), 0);
  for (const auto& [pose_id, slot] : parameters->pose_slots()) {
    ordering->AddElementToGroup(parameters->pose(pose_id), 1);
  }
  for (const auto& [id, offset] : parameters->intrinsic_offsets()) {
    // Spherical intrinsics have no block in the problem.
    if (problem.HasParameterBlock(parameters->intrinsics(id))) ordering->AddElementToGroup(parameters->intrinsics(id), 1);
  }
  return ordering;
}

ceres::Solver::Options MakeSolverOptions(const BundleAdjustmentOptions& options, size_t num_observations) {
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_SCHUR;
  solver.max_num_iterations = options.max_num_iterations;
  solver.function_tolerance = options.function_tolerance;
  solver.gradient_tolerance = options.gradient_tolerance;
  solver.parameter_tolerance = options.parameter_tolerance;
  const size_t per_thread = std::max<size_t>(options.min_observations_per_thread, 1);
  solver.num_threads = static_cast<int>(
      std::clamp<size_t>(num_observations / per_thread, 1, static_cast<size_t>(std::max(1, options.num_threads))));
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  return solver;
}

BundleAdjustmentResult AdjustBundleUntimed(const BundleAdjustmentOptions& options, SfmData* sfm_data) {
  BundleAdjustmentResult result;
  if (sfm_data->PosedViewIds().empty()) {
    result.message = "no posed view: nothing to adjust";
    return result;
  }
  BundleParameters parameters(*sfm_data);
  for (const auto& [landmark_id, landmark] : sfm_data->structure) {
    const size_t num_posed = PosedObservationsOf(*sfm_data, landmark).size();
    result.num_skipped_observations += landmark.observations.size() - num_posed;
    if (num_posed < 2) ++result.num_skipped_landmarks;
  }
  if (parameters.landmark_ids().empty()) {
    result.message = "no landmark seen by two posed views: nothing to adjust";
    return result;
  }

  ceres::Problem problem;
  result.num_observations = AddResiduals(options, *sfm_data, &parameters, &problem);
  const IndexT gauge_pose = SetPoseManifoldsAndGauge(options, *sfm_data, &parameters, &problem);
  SetIntrinsicsManifolds(options, *sfm_data, &parameters, &problem);
  AddIntrinsicsPriors(options, *sfm_data, &parameters, &problem);
  result.num_poses = parameters.num_poses();
  result.num_intrinsics = parameters.num_intrinsics();
  result.num_landmarks = parameters.landmark_ids().size();
  const ErrorSummary initial_errors = MeasureErrors(*sfm_data, parameters);
  result.initial_rms_px = initial_errors.rms_px;

  ceres::Solver::Options solver_options = MakeSolverOptions(options, result.num_observations);
  solver_options.linear_solver_ordering = EliminationOrdering(problem, &parameters);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);

  result.success = summary.IsSolutionUsable();
  result.message = summary.message;
  result.termination = ceres::TerminationTypeToString(summary.termination_type);
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  result.num_iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  if (!result.success) {  // sfm_data untouched
    result.final_rms_px = initial_errors.rms_px;
    result.num_observations_behind = initial_errors.num_behind;
    return result;
  }
  parameters.WriteBack(gauge_pose, sfm_data);
  const ErrorSummary final_errors = MeasureErrors(*sfm_data, parameters);
  result.final_rms_px = final_errors.rms_px;
  result.num_observations_behind = final_errors.num_behind;
  return result;
}

}  // namespace

BundleAdjustmentResult AdjustBundle(const BundleAdjustmentOptions& options, SfmData* sfm_data) {
  const auto start = std::chrono::steady_clock::now();
  BundleAdjustmentResult result = AdjustBundleUntimed(options, sfm_data);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void BundleAdjustmentOptions::Check() const {
  // <= 0 switches the loss or a prior off, so any number is in range; only NaN is not.
  RequireNumber(huber_loss_scale_px, "BundleAdjustmentOptions::huber_loss_scale_px (<= 0: off)");
  RequireNumber(principal_point_prior_sigma, "BundleAdjustmentOptions::principal_point_prior_sigma (<= 0: off)");
  RequireNumber(distortion_prior_sigma, "BundleAdjustmentOptions::distortion_prior_sigma (<= 0: off)");
  // Ceres' own bounds (0 iterations only evaluate the cost).
  RequireAtLeast(max_num_iterations, 0, "BundleAdjustmentOptions::max_num_iterations");
  RequireAtLeast(function_tolerance, 0.0, "BundleAdjustmentOptions::function_tolerance");
  RequireAtLeast(gradient_tolerance, 0.0, "BundleAdjustmentOptions::gradient_tolerance");
  RequireAtLeast(parameter_tolerance, 0.0, "BundleAdjustmentOptions::parameter_tolerance");
  RequireAtLeast(num_threads, 1, "BundleAdjustmentOptions::num_threads");
  RequireAtLeast<size_t>(min_observations_per_thread, 1,
                         "BundleAdjustmentOptions::min_observations_per_thread");
}

}  // namespace sfm_pruning
