#include "sfm_pruning/global/rotation_irls.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <cmath>

#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning {
namespace {

struct WeightedResiduals {
  std::vector<Eigen::Vector3d> residuals;
  std::vector<double> weights;
  double cost = 0.0;
};

WeightedResiduals EvaluateResiduals(const RotationProblem& problem,
                                    const std::vector<Eigen::Matrix3d>& rotations,
                                    const RotationIrlsOptions& options) {
  WeightedResiduals evaluated;
  evaluated.residuals = RotationResiduals(problem, rotations);
  evaluated.weights.reserve(evaluated.residuals.size());
  for (const Eigen::Vector3d& e : evaluated.residuals) {
    const double r = e.norm();
    evaluated.weights.push_back(RotationLossWeight(options.loss, r, options.loss_scale_rad));
    evaluated.cost += RotationLossValue(options.loss, r, options.loss_scale_rad);
  }
  return evaluated;
}

}  // namespace

double RotationLossWeight(RotationLoss loss, double residual_rad, double scale_rad) {
  switch (loss) {
    case RotationLoss::kL1:
      return 1.0 / std::max(residual_rad, scale_rad);
    case RotationLoss::kGemanMcClure: {
      const double s2 = scale_rad * scale_rad;
      const double ratio = s2 / (residual_rad * residual_rad + s2);
      return ratio * ratio;
    }
  }
  return 0.0;
}

double RotationLossValue(RotationLoss loss, double residual_rad, double scale_rad) {
  switch (loss) {
    case RotationLoss::kL1:
      return residual_rad >= scale_rad ? residual_rad
                                       : 0.5 * (residual_rad * residual_rad / scale_rad + scale_rad);
    case RotationLoss::kGemanMcClure: {
      const double r2 = residual_rad * residual_rad;
      const double s2 = scale_rad * scale_rad;
      return s2 * r2 / (r2 + s2);
    }
  }
  return 0.0;
}

RotationIrlsSummary RefineRotationsIrls(const RotationProblem& problem, size_t gauge_index,
                                        const RotationIrlsOptions& options,
                                        std::vector<Eigen::Matrix3d>* rotations,
                                        const ProgressCallback& progress, const std::string& stage) {
  options.Check();
  RotationIrlsSummary summary;
  WeightedResiduals current = EvaluateResiduals(problem, *rotations, options);
  summary.initial_cost = summary.final_cost = current.cost;
  if (options.uniform_first_step) std::fill(current.weights.begin(), current.weights.end(), 1.0);
  const auto max_iterations = static_cast<size_t>(std::max(options.max_iterations, 0));

  RotationIncrementSolver solver(problem.view_ids.size(), problem.edges, gauge_index, options.linear_solver);
  while (summary.num_iterations < options.max_iterations) {
    const RotationIncrementSolution step = solver.Solve(current.weights, current.residuals);
    summary.num_linear_solver_iterations += step.num_iterations;
    if (!step.success) {
      summary.failed = true;
      summary.failure_reason =
          "linear solver failed (relative residual " + std::to_string(step.relative_residual) + ")";
      return summary;
    }

    std::vector<Eigen::Matrix3d> updated = *rotations;
    double max_increment = 0.0;
    for (size_t k = 0; k < updated.size(); ++k) {
      updated[k] = updated[k] * ExpSO3(step.increments[k]);
      max_increment = std::max(max_increment, step.increments[k].norm());
    }
    WeightedResiduals next = EvaluateResiduals(problem, updated, options);
    if (!std::isfinite(next.cost)) {
      summary.failed = true;
      summary.failure_reason =
          "non-finite rotations after iteration " + std::to_string(summary.num_iterations + 1);
      return summary;
    }

    // The uniform first step does not majorise the cost, so it may raise it: not a stall.
    const bool majorised_step = !(options.uniform_first_step && summary.num_iterations == 0);
    const bool stalled =
        majorised_step && current.cost - next.cost < options.min_relative_cost_decrease * current.cost;
    *rotations = std::move(updated);
    current = std::move(next);
    ++summary.num_iterations;
    summary.final_cost = current.cost;
    summary.last_max_increment_rad = max_increment;
    ReportProgress(progress, stage, static_cast<size_t>(summary.num_iterations), max_iterations);
    if (max_increment < options.convergence_tolerance_rad || stalled) {
      summary.converged = true;
      break;
    }
  }
  return summary;
}

void RotationIrlsOptions::Check() const {
  // The weights divide by the scale.
  RequirePositiveAtMost(loss_scale_rad, 1e6, "RotationIrlsOptions::loss_scale_rad");
  // 0 iterations leave the rotations as given.
  RequireAtLeast(max_iterations, 0, "RotationIrlsOptions::max_iterations");
  RequireAtLeast(convergence_tolerance_rad, 0.0, "RotationIrlsOptions::convergence_tolerance_rad");
  // A fraction of the cost (0: never).
  RequireInRange(min_relative_cost_decrease, 0.0, 1.0, "RotationIrlsOptions::min_relative_cost_decrease");
  linear_solver.Check();
}

}  // namespace sfm_pruning
