// The capture-order prior (PruneSfM's addition, not in the paper). Photos taken along a path (a
// walk down a street, an orbit round an object, a drive, a video) are numbered in the order they
// were taken, so views close in that order are neighbours in space, and a verified pair between
// them is true far more often than a pair between views far apart in it: on a courtyard whose
// walls print alike, the pairs between views at most two apart are 80-97 % true, the others 0-13 %
// (the family benchmark's development scenes). Roberts et al. (CVPR 2011) used capture time the
// same way against duplicate structure.
//
// The order is that of the view ids (images listed by name, or a database's image ids). When it
// is used, it enters the pruning at four points:
//   - before the partition, the capture path's rotations (capture_path_rotations.hpp): the edges
//     whose rotation the robustly averaged rotations of the path's edges contradict are removed;
//   - then the capture path's model (capture_path_directions.hpp): the edges between views far
//     apart whose translation direction the model solved from the path's edges contradicts;
//   - the partition: an edge between capture neighbours weighs partition_weight_factor times its
//     weight in Louvain, so communities follow the path instead of gathering the views that see
//     one copy of the repeated structure;
//   - the loop check of subgraph pairs: a pair whose kept edges join capture neighbours ranks
//     before every other pair in the trusted forest (trusted_link_forest.hpp), so the other pairs
//     must agree with the path.
//
// kAuto uses the order only when the view graph shows that it is informative: either consecutive
// views are verified far more often than pairs are in general, or the consecutive views' relative
// rotations are far smaller than those of the verified pairs in general. A shuffled collection
// passes neither test (CaptureOrderEvidence says which one held).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct CaptureOrderOptions {
  enum class Use { kAuto, kSequential, kUnordered };
  // kSequential: the ids are the capture order; kUnordered: they are not (the paper's method);
  // kAuto: decided from the view graph (DetectCaptureOrder).
  Use use = Use::kAuto;
  // Views at most this many places apart in id order are capture neighbours.
  size_t neighbour_window_views = 2;
  // Louvain weight of an edge between capture neighbours, as a multiple of its usual weight.
  double partition_weight_factor = 10.0;
  // The capture path's rotations (capture_path_rotations.hpp): the edges between views at most
  // path_window_views apart are averaged into one rotation per view, and an edge whose relative
  // rotation deviates from them by more than max(path_max_deviation_deg, 3 s sqrt(m)) is removed
  // before the partition (s: the path edges' median residual, m: places apart). 0: off.
  size_t path_window_views = 3;
  double path_max_deviation_deg = 30.0;
  // The capture path's model (capture_path_directions.hpp): the path's edges solved by the GLOBAL
  // engine, and an edge between views more than path_window_views apart whose translation
  // direction deviates from the model's by more than max(path_max_direction_deviation_deg,
  // 3 s sqrt(m)) is removed before the partition (s: the path edges' median direction residual).
  // 0: off.
  double path_max_direction_deviation_deg = 10.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// An edge the capture path's rotations or model contradict (capture_path_rotations.hpp,
// capture_path_directions.hpp): by how many degrees, against which bound.
struct CapturePathDeviation {
  ViewPair pair;
  size_t places_apart = 0;
  double deviation_deg = 0.0;
  double bound_deg = 0.0;
};

// The connected pieces of a capture path (CaptureOrder::PathGraph) with at least 3 views, largest
// first, each as the path's graph induced on it: where no pair within the window was verified (a
// corner of a drive, a gap in the photos) the path breaks, and its pieces have no common frame.
std::vector<ViewGraph> CapturePathPieces(const ViewGraph& path);

// The bound of a capture-path check for an edge m places apart: the larger of `min_deg` and three
// times the drift a random walk of the path edges' median residual s reaches over m places,
// 3 s sqrt(m).
double CapturePathBoundDeg(double min_deg, double path_residual_deg, size_t places_apart);

// "auto", "sequential", "unordered".
const char* CaptureOrderUseName(CaptureOrderOptions::Use use);

// What the view graph says about the id order.
struct CaptureOrderEvidence {
  size_t num_views = 0;
  // Consecutive views (in id order) joined by a valid edge, over the views minus one.
  double consecutive_edge_share = 0.0;
  // Valid edges over all pairs of views.
  double edge_density = 0.0;
  // Median relative rotation of the consecutive views' edges over that of all valid edges; -1
  // when either is undefined.
  double consecutive_rotation_ratio = -1.0;
  bool by_edges = false;      // the consecutive-edge test held
  bool by_rotations = false;  // the rotation test held
  bool informative = false;   // either held
};

CaptureOrderEvidence MeasureCaptureOrder(const ViewGraph& graph);

// The capture order as the pruning uses it: empty (Used() false) when it is not used.
class CaptureOrder {
 public:
  CaptureOrder() = default;
  // Decides from `options.use` and, for kAuto, from the evidence measured on `graph`.
  CaptureOrder(const CaptureOrderOptions& options, const ViewGraph& graph);

  bool Used() const { return used_; }
  const CaptureOrderEvidence& Evidence() const { return evidence_; }
  // Whether a and b are capture neighbours (both in the graph the order was built on, at most
  // neighbour_window_views apart in id order); false when the order is not used.
  bool AreNeighbours(IndexT a, IndexT b) const;
  // How many places apart a and b are in id order; 0 when either is not in the order or the order
  // is not used.
  size_t PlacesApart(IndexT a, IndexT b) const;
  // The capture path of `graph`: its views and its valid edges between views 1 to window_views
  // places apart (empty of edges when the order is not used).
  ViewGraph PathGraph(const ViewGraph& graph, size_t window_views) const;
  double PartitionWeightFactor() const { return partition_weight_factor_; }

 private:
  bool used_ = false;
  CaptureOrderEvidence evidence_;
  std::map<IndexT, size_t> rank_;  // position of each view in id order
  size_t window_ = 0;
  double partition_weight_factor_ = 1.0;
};

}  // namespace sfm_pruning
