#include "sfm_pruning/pruning/capture_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/statistics.hpp"
#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

// Both tests are tests against a shuffled collection, where consecutive views are just two views.
// Fewer views than this say nothing either way.
constexpr size_t kMinViews = 8;
// Consecutive-edge test: in shuffled ids a consecutive pair lacks an edge as often as any pair,
// (n - 1)(1 - density) times in expectation. The order is informative when that expectation is
// large enough to be measured and at most this share of it is seen.
constexpr double kMinExpectedMissingConsecutive = 8.0;
constexpr double kMaxMissingShareOfExpected = 0.25;
// Rotation test: nearly every consecutive pair verified, and their median relative rotation at
// most this share of the verified pairs' median (shuffled dense graphs: 0.66-1.2 in the family
// benchmark's scenes; captures along a path: 0.08-0.5 where the graph is dense).
constexpr double kMinConsecutiveEdgeShare = 0.9;
constexpr double kMaxConsecutiveRotationRatio = 0.5;

}  // namespace

const char* CaptureOrderUseName(CaptureOrderOptions::Use use) {
  switch (use) {
    case CaptureOrderOptions::Use::kAuto: return "auto";
    case CaptureOrderOptions::Use::kSequential: return "sequential";
    case CaptureOrderOptions::Use::kUnordered: return "unordered";
  }
  return "unknown";
}

void CaptureOrderOptions::Check() const {
  RequireInRange<size_t>(neighbour_window_views, 1, 1000, "CaptureOrderOptions::neighbour_window_views");
  RequireInRange(partition_weight_factor, 1.0, 1e6, "CaptureOrderOptions::partition_weight_factor");
  RequireInRange<size_t>(path_window_views, 1, 1000, "CaptureOrderOptions::path_window_views");
  RequireInRange(path_max_deviation_deg, 0.0, 180.0, "CaptureOrderOptions::path_max_deviation_deg (0: off)");
  RequireInRange(path_max_direction_deviation_deg, 0.0, 180.0,
                 "CaptureOrderOptions::path_max_direction_deviation_deg (0: off)");
}

CaptureOrderEvidence MeasureCaptureOrder(const ViewGraph& graph) {
  CaptureOrderEvidence evidence;
  const std::vector<IndexT> views(graph.Nodes().begin(), graph.Nodes().end());  // id order
  const size_t n = views.size();
  evidence.num_views = n;
  if (n < 2) return evidence;
  std::vector<double> all_angles;
  graph.ForEachValidEdge([&](const ViewPair&, const ViewGraphEdge& edge) {
    all_angles.push_back(RotationAngleBetween(Eigen::Matrix3d::Identity(), edge.relative_pose.rotation));
  });
  std::vector<double> consecutive_angles;
  for (size_t k = 0; k + 1 < n; ++k) {
    const ViewGraphEdge* edge = graph.FindEdge(views[k], views[k + 1]);
    if (edge == nullptr || !edge->is_valid) continue;
    consecutive_angles.push_back(RotationAngleBetween(Eigen::Matrix3d::Identity(), edge->relative_pose.rotation));
  }
  const double num_pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n - 1);
  evidence.edge_density = static_cast<double>(all_angles.size()) / num_pairs;
  evidence.consecutive_edge_share = static_cast<double>(consecutive_angles.size()) / static_cast<double>(n - 1);
  const double all_median = Median(all_angles);
  if (!consecutive_angles.empty() && all_median > 0.0) {
    evidence.consecutive_rotation_ratio = Median(consecutive_angles) / all_median;
  }
  if (n < kMinViews) return evidence;

  const double expected_missing = static_cast<double>(n - 1) * (1.0 - evidence.edge_density);
  const double missing = static_cast<double>(n - 1 - consecutive_angles.size());
  evidence.by_edges = expected_missing >= kMinExpectedMissingConsecutive &&
                      missing <= kMaxMissingShareOfExpected * expected_missing;
  evidence.by_rotations = evidence.consecutive_edge_share >= kMinConsecutiveEdgeShare &&
                          evidence.consecutive_rotation_ratio >= 0.0 &&
                          evidence.consecutive_rotation_ratio <= kMaxConsecutiveRotationRatio;
  evidence.informative = evidence.by_edges || evidence.by_rotations;
  return evidence;
}

CaptureOrder::CaptureOrder(const CaptureOrderOptions& options, const ViewGraph& graph) {
  options.Check();
  evidence_ = MeasureCaptureOrder(graph);
  switch (options.use) {
    case CaptureOrderOptions::Use::kAuto: used_ = evidence_.informative; break;
    case CaptureOrderOptions::Use::kSequential: used_ = true; break;
    case CaptureOrderOptions::Use::kUnordered: used_ = false; break;
  }
  if (!used_) return;
  size_t position = 0;
  for (const IndexT view : graph.Nodes()) rank_[view] = position++;
  window_ = options.neighbour_window_views;
  partition_weight_factor_ = options.partition_weight_factor;
}

bool CaptureOrder::AreNeighbours(IndexT a, IndexT b) const {
  const size_t gap = PlacesApart(a, b);
  return gap >= 1 && gap <= window_;
}

size_t CaptureOrder::PlacesApart(IndexT a, IndexT b) const {
  if (!used_) return 0;
  const auto ra = rank_.find(a);
  const auto rb = rank_.find(b);
  if (ra == rank_.end() || rb == rank_.end()) return 0;
  return ra->second > rb->second ? ra->second - rb->second : rb->second - ra->second;
}

std::vector<ViewGraph> CapturePathPieces(const ViewGraph& path) {
  std::vector<ViewGraph> pieces;
  for (const NodeGroup& component : ConnectedComponents(path)) {
    if (component.size() < 3) break;  // largest first: the rest are pairs and single views
    pieces.push_back(path.InducedSubgraph(std::set<IndexT>(component.begin(), component.end())));
  }
  return pieces;
}

double CapturePathBoundDeg(double min_deg, double path_residual_deg, size_t places_apart) {
  return std::max(min_deg, 3.0 * path_residual_deg * std::sqrt(static_cast<double>(places_apart)));
}

ViewGraph CaptureOrder::PathGraph(const ViewGraph& graph, size_t window_views) const {
  ViewGraph path;
  for (const IndexT view : graph.Nodes()) path.AddNode(view);
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const size_t apart = PlacesApart(pair.first, pair.second);
    if (apart >= 1 && apart <= window_views) path.AddEdge(pair, edge);
  });
  return path;
}

}  // namespace sfm_pruning
