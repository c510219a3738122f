#include "sfm_pruning/pruning/capture_path_rotations.hpp"

#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/global/rotation_averaging.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// Degrees between an edge's relative rotation and the one its views' rotations imply, R_j R_i^T.
double DeviationDeg(const ViewGraphEdge& edge, const Eigen::Matrix3d& rotation_i, const Eigen::Matrix3d& rotation_j) {
  return RadToDeg(RotationAngleBetween(edge.relative_pose.rotation, rotation_j * rotation_i.transpose()));
}

}  // namespace

CapturePathRotationCheck CheckAgainstCapturePath(const CaptureOrderOptions& options, const CaptureOrder& order,
                                                 const ViewGraph& graph) {
  CapturePathRotationCheck check;
  if (!order.Used() || options.path_max_deviation_deg <= 0.0) return check;

  const ViewGraph path = order.PathGraph(graph, options.path_window_views);
  check.num_path_edges = path.NumValidEdges();
  if (check.num_path_edges == 0) return check;

  // Each piece of the path on its own (CapturePathPieces). A piece's rotations come from the
  // engine's robust averaging (L1, then Geman-McClure, its filter removing the path edges that
  // disagree with the others: a twin pair between neighbours is outvoted by its neighbours); the
  // residual scale s is the median over the pieces' path edges.
  std::map<IndexT, Eigen::Matrix3d> rotations;
  std::map<IndexT, size_t> piece_of;
  std::vector<double> residuals;
  size_t piece = 0;
  for (ViewGraph& piece_graph : CapturePathPieces(path)) {
    std::map<IndexT, Eigen::Matrix3d> piece_rotations;
    const RotationAveragingResult averaged =
        EstimateGlobalRotations(&piece_graph, RotationAveragingOptions(), &piece_rotations);
    if (!averaged.success) continue;
    for (const auto& [view, rotation] : piece_rotations) {
      rotations[view] = rotation;
      piece_of[view] = piece;
    }
    piece_graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
      const auto ri = piece_rotations.find(pair.first);
      const auto rj = piece_rotations.find(pair.second);
      if (ri == piece_rotations.end() || rj == piece_rotations.end()) return;
      residuals.push_back(DeviationDeg(edge, ri->second, rj->second));
    });
    ++piece;
  }
  if (rotations.empty()) return check;
  check.applied = true;
  check.num_path_views = rotations.size();
  check.num_path_pieces = piece;
  check.path_residual_deg = Median(std::move(residuals));

  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const auto ri = rotations.find(pair.first);
    const auto rj = rotations.find(pair.second);
    if (ri == rotations.end() || rj == rotations.end()) return;
    if (piece_of.at(pair.first) != piece_of.at(pair.second)) return;  // no common frame
    const size_t apart = order.PlacesApart(pair.first, pair.second);
    const double deviation = DeviationDeg(edge, ri->second, rj->second);
    const double bound = CapturePathBoundDeg(options.path_max_deviation_deg, check.path_residual_deg, apart);
    if (deviation > bound) check.removed.push_back({pair, apart, deviation, bound});
  });
  return check;
}

}  // namespace sfm_pruning
