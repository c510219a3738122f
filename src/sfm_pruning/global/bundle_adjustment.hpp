// Bundle adjustment of the GLOBAL engine (METHOD.md §2.4): joint refinement of camera poses,
// landmarks and optionally intrinsics by minimising the robustified reprojection error (Ceres,
// sparse Schur complement with the landmarks eliminated first).
//
// What takes part: every pose used by a posed view (views sharing an id_pose share one pose
// block), every landmark with at least two posed observations, and every intrinsic of a posed
// view. Observations made by unposed views are skipped; landmarks seen by fewer than two posed
// views are left untouched (structure_filtering.hpp removes them).
//
// Gauge (a reconstruction is defined up to a similarity, 7 dof): with fix_first_pose the pose of
// the smallest posed view id is held constant (6 dof). With fix_scale as well, one coordinate of
// a second camera's centre is held constant too: the pose farthest from the first one, along
// the axis of their largest offset. That removes the remaining scale dof exactly instead of
// leaving a 1-d null space for the Levenberg-Marquardt damping to absorb (GLOMAP's choice), so
// the normal equations are non-singular and the scale cannot drift between rounds.
#pragma once

#include <cstddef>
#include <set>
#include <string>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct BundleAdjustmentOptions {
  // Huber loss scale in pixels: residuals above it weigh linearly (METHOD.md: ~1 px).
  // <= 0 means plain least squares.
  double huber_loss_scale_px = 1.0;

  // Intrinsics refinement (per intrinsic id; all views sharing it share the block). The engine
  // decides; by default intrinsics are held constant.
  bool refine_focal = false;            // f, or fx and fy
  bool refine_principal_point = false;  // cx, cy (Strecha needs it: ~16 px off centre)
  bool refine_distortion = false;       // k1.. / t1, t2 of models that have them
  // Intrinsic ids held constant whatever the flags above (e.g. calibrated cameras).
  std::set<IndexT> constant_intrinsics;
  // Intrinsic ids whose principal point stays put even with refine_principal_point (cameras with
  // a focal prior from EXIF: like COLMAP, their principal point is left at the image centre).
  std::set<IndexT> constant_principal_point;
  // Weak Gaussian priors on the refined principal point (around the image centre, sigma =
  // principal_point_prior_sigma * max(width, height)) and distortion coefficients (around 0,
  // sigma = distortion_prior_sigma); <= 0 switches a prior off. Why: a sparse ring of narrow
  // views (templeSparseRing: 16 views, 24° field of view) hardly observes them, and free they
  // trade against each other: the principal point wandered 38 px and k1 to -0.26 on undistorted
  // images (AUC@5 63). The priors cost nothing where the data determine the parameters (a
  // Strecha principal point 16 px off centre is 0.05 sigma; books' k1 = -0.046 is 0.5 sigma).
  double principal_point_prior_sigma = 0.1;
  double distortion_prior_sigma = 0.1;

  // Gauge, see above. fix_scale is only used together with fix_first_pose.
  bool fix_first_pose = true;
  bool fix_scale = true;

  int max_num_iterations = 100;
  // Ceres' relative cost decrease at which it stops.
  double function_tolerance = 1e-6;
  double gradient_tolerance = 1e-10;
  double parameter_tolerance = 1e-8;
  // Threads for Jacobian evaluation and the Schur elimination (Ceres caps it at the hardware
  // concurrency). 1 gives bitwise reproducible results; with more threads Ceres sums partial
  // costs and Schur blocks in scheduling order, so results can differ in the last bits.
  int num_threads = 1;
  // Observations per Ceres thread: fewer threads on smaller problems. Ceres' threads meet at
  // every step of every iteration, which on a few thousand observations costs more than the
  // parallel evaluation brings (templeSparseRing's focal search, 583 observations: 0.17 s with 2
  // threads, 0.11 s with 1; its 4,750-observation adjustments take the same time either way).
  size_t min_observations_per_thread = 2500;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct BundleAdjustmentResult {
  bool success = false;
  std::string message;      // why it failed, or Ceres' termination message
  std::string termination;  // Ceres TerminationType name ("CONVERGENCE", "NO_CONVERGENCE", ...)

  double initial_cost = 0.0;  // Ceres cost (0.5 * sum of robustified squared residuals)
  double final_cost = 0.0;
  // Root mean square of the residual coordinates in pixels over the observations in the problem
  // (not robustified): 1 px Gaussian noise per coordinate gives ~1 px. Observations behind a
  // camera are left out of the RMS and counted in num_observations_behind.
  double initial_rms_px = 0.0;
  double final_rms_px = 0.0;
  int num_iterations = 0;  // Ceres iterations, successful or not
  double seconds = 0.0;    // wall time of the whole call (problem construction + solve)

  size_t num_poses = 0;
  size_t num_intrinsics = 0;
  size_t num_landmarks = 0;
  size_t num_observations = 0;
  size_t num_observations_behind = 0;        // after the solve
  size_t num_skipped_observations = 0;       // made by unposed views
  size_t num_skipped_landmarks = 0;          // fewer than two posed observations
};

// Refines sfm_data->poses, the landmarks' X and (as requested) sfm_data->intrinsics in place.
// Fails without touching anything when there is nothing to adjust (no posed view, no landmark
// with two posed observations). Never prints.
BundleAdjustmentResult AdjustBundle(const BundleAdjustmentOptions& options, SfmData* sfm_data);

}  // namespace sfm_pruning
