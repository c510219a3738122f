#include "sfm_pruning/global/rotation_averaging.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "sfm_pruning/global/rotation_initialization.hpp"
#include "sfm_pruning/global/rotation_irls.hpp"
#include "sfm_pruning/global/rotation_problem.hpp"
#include "sfm_pruning/sfm/pose.hpp"
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

bool HasEveryView(const std::map<IndexT, Eigen::Matrix3d>& rotations,
                  const std::vector<IndexT>& view_ids) {
  return std::all_of(view_ids.begin(), view_ids.end(),
                     [&rotations](IndexT id) { return rotations.count(id) > 0; });
}

size_t DenseIndexOf(const std::vector<IndexT>& sorted_ids, IndexT id) {
  return static_cast<size_t>(std::lower_bound(sorted_ids.begin(), sorted_ids.end(), id) -
                             sorted_ids.begin());
}

RotationResidualStats SummarizeResiduals(std::vector<double> residuals_deg) {
  RotationResidualStats stats;
  stats.num_edges = residuals_deg.size();
  if (residuals_deg.empty()) return stats;
  std::sort(residuals_deg.begin(), residuals_deg.end());
  const size_t n = residuals_deg.size();
  stats.mean_deg = std::accumulate(residuals_deg.begin(), residuals_deg.end(), 0.0) / n;
  stats.median_deg = n % 2 == 1 ? residuals_deg[n / 2]
                                : 0.5 * (residuals_deg[n / 2 - 1] + residuals_deg[n / 2]);
  stats.max_deg = residuals_deg.back();
  return stats;
}

// One IRLS stage; returns false (with result->failure_reason set) when it failed or when its
// robust cost rose: each step majorises the cost, so a rise means the linearisation broke down.
bool RunStage(const RotationProblem& problem, size_t gauge, const RotationIrlsOptions& stage_options,
              const std::string& stage_name, const ProgressCallback& progress,
              std::vector<Eigen::Matrix3d>* estimate, RotationIrlsSummary* summary,
              RotationAveragingResult* result) {
  *summary = RefineRotationsIrls(problem, gauge, stage_options, estimate, progress, stage_name);
  result->num_linear_solver_iterations += summary->num_linear_solver_iterations;
  if (summary->failed) {
    result->failure_reason = stage_name + ": " + summary->failure_reason;
    return false;
  }
  constexpr double kCostRiseTolerance = 1e-6;  // relative, above rounding of the sums
  if (summary->final_cost > summary->initial_cost * (1.0 + kCostRiseTolerance) + 1e-15) {
    result->failure_reason = stage_name + ": diverged (robust cost rose from " +
                             std::to_string(summary->initial_cost) + " to " +
                             std::to_string(summary->final_cost) + ")";
    return false;
  }
  return true;
}

}  // namespace

RotationAveragingResult EstimateGlobalRotations(ViewGraph* graph,
                                                const RotationAveragingOptions& options,
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
  RotationIncrementSolverOptions linear_solver;
  linear_solver.relative_tolerance = options.linear_solver_relative_tolerance;
  linear_solver.max_iterations = options.max_linear_solver_iterations;
  RotationIrlsOptions l1_options;
  l1_options.loss = RotationLoss::kL1;
  l1_options.loss_scale_rad = DegToRad(options.l1_residual_floor_deg);
  l1_options.max_iterations = options.max_l1_iterations;
  l1_options.convergence_tolerance_rad = options.l1_convergence_tolerance_rad;
  l1_options.min_relative_cost_decrease = options.l1_min_relative_cost_decrease;
  l1_options.uniform_first_step = true;
  l1_options.linear_solver = linear_solver;
  RotationIrlsOptions robust_options = l1_options;
  robust_options.loss = RotationLoss::kGemanMcClure;
  robust_options.loss_scale_rad = DegToRad(options.irls_loss_scale_deg);
  robust_options.max_iterations = options.max_irls_iterations;
  robust_options.convergence_tolerance_rad = options.convergence_tolerance_rad;
  robust_options.min_relative_cost_decrease = 0.0;  // run to convergence
  robust_options.uniform_first_step = false;  // starts from the L1 estimate: weights are meaningful

  RotationIrlsSummary l1_summary;
  const bool l1_ok = RunStage(problem, gauge, l1_options, "rotation averaging (L1)", progress,
                              &estimate, &l1_summary, &result);
  result.num_l1_iterations = l1_summary.num_iterations;
  result.l1_converged = l1_summary.converged;
  if (!l1_ok) return result;
  RotationIrlsSummary robust_summary;
  const bool robust_ok = RunStage(problem, gauge, robust_options, "rotation averaging (IRLS)",
                                  progress, &estimate, &robust_summary, &result);
  result.num_irls_iterations = robust_summary.num_iterations;
  result.converged = robust_summary.converged;
  if (!robust_ok) return result;

  // Filtering, then the largest component of what is left.
  const std::vector<Eigen::Vector3d> residuals = RotationResiduals(problem, estimate);
  std::vector<double> residuals_deg(residuals.size());
  for (size_t k = 0; k < residuals.size(); ++k) residuals_deg[k] = RadToDeg(residuals[k].norm());
  result.residuals_before_filtering = SummarizeResiduals(residuals_deg);
  if (options.filter_edges) {
    for (size_t k = 0; k < residuals.size(); ++k) {
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
  std::set_union(component.dropped.begin(), component.dropped.end(),
                 final_component.dropped.begin(), final_component.dropped.end(),
                 std::back_inserter(result.dropped_views));

  std::vector<double> kept_residuals_deg;
  for (size_t k = 0; k < residuals.size(); ++k) {
    if (skeleton.HasValidEdge(problem.pairs[k].first, problem.pairs[k].second)) {
      kept_residuals_deg.push_back(residuals_deg[k]);
    }
  }
  result.residuals = SummarizeResiduals(std::move(kept_residuals_deg));

  rotations->clear();
  for (IndexT id : result.estimated_views) {
    rotations->emplace(id, estimate[DenseIndexOf(problem.view_ids, id)]);
  }
  if (options.remove_dropped_views_from_graph) graph->RemoveNodes(result.dropped_views);
  result.success = true;
  return result;
}

}  // namespace sfm_pruning
