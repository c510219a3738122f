// Rotation averaging, the first step of the GLOBAL engine (METHOD.md §2.1):
//   1. keep the largest connected component of valid edges;
//   2. initialise by the maximum spanning tree (weights = inliers; root = identity), unless the
//      caller passes rotations for every view of that component;
//   3. L1 stage: IRLS with w = 1 / max(r, floor) (robust to whole mis-initialised subtrees);
//   4. robust stage: IRLS with Geman-McClure weights of scale irls_loss_scale_deg
//      (Chatterjee & Govindu, "Robust Relative Rotation Averaging", TPAMI 2018);
//   5. filtering: invalidate edges whose relative rotation disagrees with the estimate by more
//      than max_relative_rotation_error_deg (kRotationResidual) and keep the largest component;
//   6. when edges were filtered, the robust stage again on the kept edges.
// Each IRLS iteration solves a sparse n x n Laplacian for three right-hand sides
// (rotation_increment_solver.hpp); nothing dense of size n is formed.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "sfm_pruning/util/progress.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct RotationAveragingOptions {
  // Edges whose R_ij is farther than this from R_j R_i^T after refinement are invalidated.
  double max_relative_rotation_error_deg = 10.0;
  bool filter_edges = true;
  // After filtering, run the robust stage again on the kept edges only (removes the small pull
  // the filtered outliers still exert through their non-zero Geman-McClure weights).
  bool refine_after_filtering = true;
  // Erase the views outside the final component (and their edges) from the graph, as
  // KeepLargestComponent does. Off by default: the graph keeps every edge's record and the
  // returned rotations say which views were estimated.
  bool remove_dropped_views_from_graph = false;

  // L1 stage: only needs to bring every rotation into the basin of the robust stage, so it
  // stops early (a few degrees of accuracy are enough).
  int max_l1_iterations = 30;
  double l1_residual_floor_deg = 0.05;  // residuals below this get the same (largest) weight
  double l1_convergence_tolerance_rad = 1e-4;
  // The L1 cost has a slow sublinear tail once the outliers are down-weighted; stop when an
  // iteration lowers it by less than this fraction.
  double l1_min_relative_cost_decrease = 1e-4;

  // Robust stage (Geman-McClure). Chatterjee & Govindu use a scale of about 5 degrees: edges
  // beyond ~3 scales barely count.
  int max_irls_iterations = 100;
  double irls_loss_scale_deg = 5.0;
  // Converged once no rotation moves by more than this in one iteration.
  double convergence_tolerance_rad = 1e-8;

  // Conjugate gradients of each step (rotation_increment_solver.hpp).
  double linear_solver_relative_tolerance = 1e-10;
  int max_linear_solver_iterations = 1000;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Angles between R_ij and R_j R_i^T over a set of edges, in degrees (0 for an empty set).
struct RotationResidualStats {
  size_t num_edges = 0;
  double mean_deg = 0.0;
  double median_deg = 0.0;
  double max_deg = 0.0;
};

struct RotationAveragingResult {
  // false: nothing was estimated and *rotations is unchanged; failure_reason says why
  // ("no valid edge", "linear solver failed ...", "diverged ...").
  bool success = false;
  std::string failure_reason;
  // The last robust stage reached convergence_tolerance_rad (the estimate is usable either way).
  bool converged = false;
  bool l1_converged = false;
  int num_l1_iterations = 0;
  int num_irls_iterations = 0;           // both robust runs (before and after filtering)
  int num_linear_solver_iterations = 0;  // CG iterations over all steps and coordinates

  bool initialized_from_input = false;  // else from the maximum spanning tree
  // The view held fixed: the tree root (rotation = identity) or, with a given initialisation,
  // the smallest id; the smallest kept id if filtering dropped it.
  IndexT gauge_view = kUndefinedIndex;

  RotationResidualStats residuals_before_filtering;  // every edge of the estimated component
  RotationResidualStats residuals;                   // the valid edges between returned views

  std::vector<ViewPair> filtered_edges;  // invalidated here (kRotationResidual), ViewPair order
  std::vector<IndexT> estimated_views;   // the final largest component, sorted = keys of *rotations
  // Every other node of the graph, sorted: outside the initial largest component, or cut off by
  // the filtering.
  std::vector<IndexT> dropped_views;
};

// `rotations` (world -> camera, sfm/pose.hpp) is in/out: when it holds a rotation for every view
// of the largest component it is the initial estimate, otherwise it is ignored. On success it
// is replaced by the estimates of `estimated_views` exactly. `graph` gets the filtered edges
// invalidated (and, with remove_dropped_views_from_graph, the dropped views erased).
// Progress stages: "rotation averaging (L1)", "rotation averaging (IRLS)".
// Throws std::invalid_argument for null pointers.
RotationAveragingResult EstimateGlobalRotations(ViewGraph* graph, const RotationAveragingOptions& options,
                                                std::map<IndexT, Eigen::Matrix3d>* rotations,
                                                const ProgressCallback& progress = {});

}  // namespace sfm_pruning
