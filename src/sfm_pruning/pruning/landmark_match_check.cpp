#include "sfm_pruning/pruning/landmark_match_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace sfm_pruning {
namespace {

// One side of an edge: its view, the subgraph it lies in, and where that subgraph puts it.
struct EdgeSide {
  IndexT view_id = kUndefinedIndex;
  const SubgraphSolution* solution = nullptr;
  const std::map<ObservationKey, IndexT>* landmark_of = nullptr;
  const Pose* pose = nullptr;
  const CameraIntrinsics* intrinsics = nullptr;
  const FeatureSet* features = nullptr;
};

// The landmark of `side`'s feature in its own subgraph, if it has one.
std::optional<Eigen::Vector3d> LandmarkOf(const EdgeSide& side, IndexT feature) {
  const auto it = side.landmark_of->find({side.view_id, feature});
  if (it == side.landmark_of->end()) return std::nullopt;
  return side.solution->landmarks.at(it->second).X;
}

// Whether the landmark of `from`'s feature, carried by `to_frame` into the other subgraph, lies
// off the ray of `to`'s feature; nullopt when `from`'s feature has no landmark.
std::optional<bool> Contradicts(const EdgeSide& from, IndexT from_feature, const EdgeSide& to, IndexT to_feature,
                                const Similarity3& to_frame, double max_angle_rad) {
  const std::optional<Eigen::Vector3d> X = LandmarkOf(from, from_feature);
  if (!X) return std::nullopt;
  const Eigen::Vector2d pixel = to.features->Position(to_feature);
  return RayAngleToPoint(*to.intrinsics, *to.pose, pixel, to_frame.Apply(*X)) > max_angle_rad;
}

}  // namespace

double RayAngleToPoint(const CameraIntrinsics& intrinsics, const Pose& pose, const Eigen::Vector2d& pixel,
                       const Eigen::Vector3d& X) {
  const Eigen::Vector3d ray = pose.rotation.transpose() * intrinsics.Unproject(pixel);
  const Eigen::Vector3d to_point = X - pose.center;
  return std::atan2(ray.cross(to_point).norm(), ray.dot(to_point));
}

LandmarkMatchCheckReport CheckMatchesAgainstLandmarks(const LandmarkMatchCheckOptions& options,
                                                      const std::vector<AcceptedSubgraph>& accepted,
                                                      const std::vector<AlignedSubgraphs>& pairs,
                                                      const SfmData& views_and_intrinsics,
                                                      const FeaturesPerView& features, ViewGraph* graph) {
  LandmarkMatchCheckReport report;
  if (!(options.max_angle_deg > 0.0)) return report;
  const double max_angle_rad = DegToRad(options.max_angle_deg);
  std::vector<std::map<ObservationKey, IndexT>> landmark_of;
  for (const AcceptedSubgraph& subgraph : accepted) landmark_of.push_back(IndexLandmarksByObservation(subgraph.solution));
  // (a, b) -> the transform from subgraph b's frame into subgraph a's, both ways round.
  std::map<std::pair<int, int>, Similarity3> into;
  for (const AlignedSubgraphs& pair : pairs) {
    into[{pair.k1, pair.k2}] = pair.k2_to_k1;
    into[{pair.k2, pair.k1}] = pair.k2_to_k1.Inverse();
  }

  const auto side_of = [&](IndexT view_id, int k) -> std::optional<EdgeSide> {
    const SubgraphSolution& solution = accepted[static_cast<size_t>(k)].solution;
    const auto pose = solution.poses.find(view_id);
    const CameraIntrinsics* intrinsics = views_and_intrinsics.FindIntrinsics(view_id);
    const auto view_features = features.find(view_id);
    if (pose == solution.poses.end() || intrinsics == nullptr || view_features == features.end()) return std::nullopt;
    return EdgeSide{view_id, &solution, &landmark_of[static_cast<size_t>(k)], &pose->second, intrinsics,
                    &view_features->second};
  };

  for (const EdgeOfSubgraphs& edge : EdgesOfAcceptedSubgraphs(*graph, accepted)) {
    const auto second_to_first = into.find({edge.k_first, edge.k_second});
    if (edge.k_first == edge.k_second || second_to_first == into.end()) continue;
    const Similarity3& first_to_second = into.at({edge.k_second, edge.k_first});
    const std::optional<EdgeSide> first = side_of(edge.pair.first, edge.k_first);
    const std::optional<EdgeSide> second = side_of(edge.pair.second, edge.k_second);
    if (!first || !second) continue;

    ViewGraphEdge* graph_edge = graph->MutableEdge(edge.pair.first, edge.pair.second);
    ++report.num_edges;
    report.num_matches += graph_edge->matches.size();
    std::vector<FeatureMatch> kept;
    kept.reserve(graph_edge->matches.size());
    for (const FeatureMatch& match : graph_edge->matches) {
      const std::optional<bool> forward = Contradicts(*first, match.i, *second, match.j, first_to_second, max_angle_rad);
      const std::optional<bool> backward =
          Contradicts(*second, match.j, *first, match.i, second_to_first->second, max_angle_rad);
      if (forward || backward) ++report.num_tested;
      if (forward.value_or(false) || backward.value_or(false)) {
        ++report.num_dropped;
        continue;
      }
      kept.push_back(match);
    }
    graph_edge->matches = std::move(kept);
    if (graph_edge->matches.size() < options.min_matches) report.emptied.push_back(edge.pair);
  }
  return report;
}

}  // namespace sfm_pruning
