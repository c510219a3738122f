#include "sfm_pruning/global/rotation_averaging.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "sfm_pruning/global/rotation_initialization.hpp"
#include "sfm_pruning/global/rotation_irls.hpp"
#include "sfm_pruning/global/rotation_problem.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/statistics.hpp"
#include "sfm_pruning/view_graph/components.hpp"
#include "sfm_pruning/view_graph/spanning_tree.hpp"

namespace sfm_pruning {
namespace {

// Every node of `graph` and its valid edges without their matches: averaging needs only the
// relative rotations and weights, and copying millions of matches would dominate its cost.
ViewGraph RotationSkeleton(const ViewGraph& graph) {
  ViewGraph skeleton;
  for (IndexT id : graph.Nodes()) skeleton.AddNode(id);
  graph.ForEachValidEdge([&skeleton](const ViewPair& pair, const ViewGraphEdge& edge) {
    ViewGraphEdge light;
    light.relative_pose = edge.relative_pose;
    light.weight = edge.weight;
    skeleton.AddEdge(pair, std::move(light));
  });
  return skeleton;
}

bool HasEveryView(const std::map<IndexT, Eigen::Matrix3d>& rotations, const std::vector<IndexT>& view_ids) {
  return std::all_of(view_ids.begin(), view_ids.end(),
                     [&rotations](IndexT id) { return rotations.count(id) > 0; });
}

size_t DenseIndexOf(const std::vector<IndexT>& sorted_ids, IndexT id) {
  return static_cast<size_t>(std::lower_bound(sorted_ids.begin(), sorted_ids.end(), id) - sorted_ids.begin());
}

RotationResidualStats SummarizeResiduals(const std::vector<double>& residuals_deg) {
  RotationResidualStats stats;
  stats.num_edges = residuals_deg.size();
  stats.mean_deg = Mean(residuals_deg);
  stats.median_deg = Median(residuals_deg);
  stats.max_deg = Max(residuals_deg);
  return stats;
}

RotationResidualStats ResidualStats(const RotationProblem& problem,
                                    const std::vector<Eigen::Matrix3d>& rotations,
                                    std::vector<double>* residuals_deg = nullptr) {
  const std::vector<Eigen::Vector3d> residuals = RotationResiduals(problem, rotations);
  std::vector<double> angles_deg(residuals.size());
  for (size_t k = 0; k < residuals.size(); ++k) angles_deg[k] = RadToDeg(residuals[k].norm());
  if (residuals_deg != nullptr) *residuals_deg = angles_deg;
  return SummarizeResiduals(angles_deg);
}

RotationIrlsOptions L1StageOptions(const RotationAveragingOptions& options, bool from_tree) {
  RotationIrlsOptions stage;
  stage.loss = RotationLoss::kL1;
  stage.loss_scale_rad = DegToRad(options.l1_residual_floor_deg);
  stage.max_iterations = options.max_l1_iterations;
  stage.convergence_tolerance_rad = options.l1_convergence_tolerance_rad;
  stage.min_relative_cost_decrease = options.l1_min_relative_cost_decrease;
  // Only the tree leaves residuals at exactly 0 (see RotationIrlsOptions); a caller's estimate
  // is better served by its own residuals.
  stage.uniform_first_step = from_tree;
  stage.linear_solver.relative_tolerance = options.linear_solver_relative_tolerance;
  stage.linear_solver.max_iterations = options.max_linear_solver_iterations;
  return stage;
}

RotationIrlsOptions RobustStageOptions(const RotationAveragingOptions& options) {
  RotationIrlsOptions stage = L1StageOptions(options, false);
  stage.loss = RotationLoss::kGemanMcClure;
  stage.loss_scale_rad = DegToRad(options.irls_loss_scale_deg);
  stage.max_iterations = options.max_irls_iterations;
  stage.convergence_tolerance_rad = options.convergence_tolerance_rad;
  stage.min_relative_cost_decrease = 0.0;  // run to convergence
  return stage;
}

// One IRLS stage; false (with result->failure_reason set) when it failed. With
// `cost_must_not_rise` a rise of the robust cost is reported as divergence: every step of a
// stage without a uniform first step majorises its cost, so a rise means the linearisation
// broke down.
bool RunStage(const RotationProblem& problem, size_t gauge, const RotationIrlsOptions& stage_options,
              const std::string& stage_name, bool cost_must_not_rise, const ProgressCallback& progress,
              std::vector<Eigen::Matrix3d>* estimate, RotationIrlsSummary* summary,
              RotationAveragingResult* result) {
  *summary = RefineRotationsIrls(problem, gauge, stage_options, estimate, progress, stage_name);
  result->num_linear_solver_iterations += summary->num_linear_solver_iterations;
  if (summary->failed) {
    result->failure_reason = stage_name + ": " + summary->failure_reason;
    return false;
  }
  constexpr double kCostRiseTolerance = 1e-6;  // relative, above rounding of the sums
  if (cost_must_not_rise &&
      summary->final_cost > summary->initial_cost * (1.0 + kCostRiseTolerance) + 1e-15) {
    result->failure_reason = stage_name + ": diverged (robust cost rose from " +
                             std::to_string(summary->initial_cost) + " to " +
                             std::to_string(summary->final_cost) + ")";
    return false;
  }
  return true;
}

// The robust stage; accumulates into the result's IRLS counters (it runs again after filtering).
bool RunRobustStage(const RotationProblem& problem, size_t gauge, const RotationAveragingOptions& options,
                    const ProgressCallback& progress, std::vector<Eigen::Matrix3d>* estimate,
                    RotationAveragingResult* result) {
  RotationIrlsSummary summary;
  const bool ok = RunStage(problem, gauge, RobustStageOptions(options), "rotation averaging (IRLS)", true,
                           progress, estimate, &summary, result);
  result->num_irls_iterations += summary.num_iterations;
  result->converged = summary.converged;
  return ok;
}

}  // namespace

RotationAveragingResult EstimateGlobalRotations(ViewGraph* graph, const RotationAveragingOptions& options,
                                                std::map<IndexT, Eigen::Matrix3d>* rotations,
                                                const ProgressCallback& progress) {
  if (graph == nullptr || rotations == nullptr) {
    throw std::invalid_argument("EstimateGlobalRotations: null graph or rotations");
  }
  RotationAveragingResult result;
  ViewGraph skeleton = RotationSkeleton(*graph);
  const LargestComponentSelection component = KeepLargestComponent(&skeleton);
  if (skeleton.NumValidEdges() == 0) {
    result.failure_reason = "no valid edge";
    result.dropped_views.assign(graph->Nodes().begin(), graph->Nodes().end());
    return result;
  }

  // Initial estimate and gauge.
  const RotationProblem problem = BuildRotationProblem(skeleton);
  std::vector<Eigen::Matrix3d> estimate;
  size_t gauge = 0;
  if (HasEveryView(*rotations, problem.view_ids)) {
    estimate = DenseRotations(problem, *rotations);
    result.initialized_from_input = true;  // gauge: the smallest id
  } else {
    const SpanningTree tree = MaximumSpanningTree(skeleton);
    estimate = DenseRotations(problem, RotationsAlongSpanningTree(skeleton, tree));
    gauge = DenseIndexOf(problem.view_ids, tree.root);  // keeps the root at the identity
  }
  result.gauge_view = problem.view_ids[gauge];

  // Refinement: L1 stage, then the robust stage.
  RotationIrlsSummary l1_summary;
  const bool l1_ok = RunStage(problem, gauge, L1StageOptions(options, !result.initialized_from_input),
                              "rotation averaging (L1)", false, progress, &estimate, &l1_summary, &result);
  result.num_l1_iterations = l1_summary.num_iterations;
  result.l1_converged = l1_summary.converged;
  if (!l1_ok || !RunRobustStage(problem, gauge, options, progress, &estimate, &result)) {
    return result;
  }

  // Filtering, then the largest component of what is left.
  std::vector<double> residuals_deg;
  result.residuals_before_filtering = ResidualStats(problem, estimate, &residuals_deg);
  if (options.filter_edges) {
    for (size_t k = 0; k < residuals_deg.size(); ++k) {
      if (residuals_deg[k] <= options.max_relative_rotation_error_deg) continue;
      const ViewPair& pair = problem.pairs[k];
      const EdgeInvalidation why{EdgeInvalidReason::kRotationResidual, residuals_deg[k],
                                 options.max_relative_rotation_error_deg};
      graph->InvalidateEdge(pair.first, pair.second, why);
      skeleton.InvalidateEdge(pair.first, pair.second, why);
      result.filtered_edges.push_back(pair);
    }
  }
  const LargestComponentSelection final_component = KeepLargestComponent(&skeleton);
  result.estimated_views = final_component.kept;
  std::set_union(component.dropped.begin(), component.dropped.end(), final_component.dropped.begin(),
                 final_component.dropped.end(), std::back_inserter(result.dropped_views));

  // Re-solve on the kept edges: Geman-McClure never gives an outlier exactly zero weight, so
  // the estimate above still carries a small pull from the edges just filtered.
  const RotationProblem final_problem = BuildRotationProblem(skeleton);
  std::vector<Eigen::Matrix3d> final_estimate =
      DenseRotations(final_problem, RotationsById(problem, estimate));
  if (!result.filtered_edges.empty() && options.refine_after_filtering) {
    const bool gauge_kept =
        std::binary_search(final_problem.view_ids.begin(), final_problem.view_ids.end(), result.gauge_view);
    if (!gauge_kept) result.gauge_view = final_problem.view_ids.front();
    if (!RunRobustStage(final_problem, DenseIndexOf(final_problem.view_ids, result.gauge_view), options,
                        progress, &final_estimate, &result)) {
      return result;
    }
  }
  result.residuals = ResidualStats(final_problem, final_estimate);

  *rotations = RotationsById(final_problem, final_estimate);
  if (options.remove_dropped_views_from_graph) graph->RemoveNodes(result.dropped_views);
  result.success = true;
  return result;
}

void RotationAveragingOptions::Check() const {
  // A threshold on an angle between two rotations; the stages' scales only need to be positive.
  RequirePositiveAtMost(max_relative_rotation_error_deg, 180.0,
                        "RotationAveragingOptions::max_relative_rotation_error_deg");
  RequireAtLeast(max_l1_iterations, 0, "RotationAveragingOptions::max_l1_iterations");
  RequirePositiveAtMost(l1_residual_floor_deg, 1e6, "RotationAveragingOptions::l1_residual_floor_deg");
  RequireAtLeast(l1_convergence_tolerance_rad, 0.0, "RotationAveragingOptions::l1_convergence_tolerance_rad");
  RequireInRange(l1_min_relative_cost_decrease, 0.0, 1.0,
                 "RotationAveragingOptions::l1_min_relative_cost_decrease");
  RequireAtLeast(max_irls_iterations, 0, "RotationAveragingOptions::max_irls_iterations");
  RequirePositiveAtMost(irls_loss_scale_deg, 1e6, "RotationAveragingOptions::irls_loss_scale_deg");
  RequireAtLeast(convergence_tolerance_rad, 0.0, "RotationAveragingOptions::convergence_tolerance_rad");
  // As RotationIncrementSolverOptions, which the stages are given.
  RequirePositiveAtMost(linear_solver_relative_tolerance, 1.0,
                        "RotationAveragingOptions::linear_solver_relative_tolerance");
  RequireAtLeast(max_linear_solver_iterations, 1, "RotationAveragingOptions::max_linear_solver_iterations");
}

}  // namespace sfm_pruning
