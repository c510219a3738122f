#include "sfm_pruning/pruning/landmark_match_check.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <map>
#include <optional>
#include <utility>

#include "sfm_pruning/pruning/subgraph_edge_placement.hpp"

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

// The other side of a check and the transform that carries the landmarks into its frame.
struct Direction {
  EdgeSide to;
  Similarity3 into_to;
};

// `to`'s view placed in `from`'s subgraph by the edge's EPnP (subgraph_edge_placement.hpp), as
// the side `from`'s landmarks are checked against (identity transform); nullopt when it cannot be
// placed. `placed` holds the pose the returned side points to.
std::optional<Direction> PlacedDirection(const ViewGraph& graph, const EdgeSide& from, const EdgeSide& to,
                                         const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                         Pose* placed) {
  const EdgePlacement placement = PlaceViewInSubgraph(graph, from.view_id, to.view_id, *from.solution,
                                                      *from.landmark_of, views_and_intrinsics, features);
  if (placement.status != EdgePlacementStatus::kPlaced) return std::nullopt;
  *placed = placement.pose_j_in_k1;
  EdgeSide side = to;
  side.pose = placed;
  return Direction{side, Similarity3()};
}

}  // namespace

double RayAngleToPoint(const CameraIntrinsics& intrinsics, const Pose& pose, const Eigen::Vector2d& pixel,
                       const Eigen::Vector3d& X) {
  return AngleBetweenVectors(pose.rotation.transpose() * intrinsics.Unproject(pixel), X - pose.center);
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
    if (edge.k_first == edge.k_second) continue;
    const std::optional<EdgeSide> first = side_of(edge.pair.first, edge.k_first);
    const std::optional<EdgeSide> second = side_of(edge.pair.second, edge.k_second);
    if (!first || !second) continue;
    // How one side's landmarks reach the other side's rays: through the pair's transform, or,
    // without one, through the other view placed in this side's subgraph by the edge's own EPnP.
    std::optional<Direction> forward;   // first's landmarks against second's rays
    std::optional<Direction> backward;  // second's landmarks against first's rays
    Pose second_in_first;
    Pose first_in_second;
    const auto second_to_first = into.find({edge.k_first, edge.k_second});
    if (second_to_first != into.end()) {
      forward = Direction{*second, into.at({edge.k_second, edge.k_first})};
      backward = Direction{*first, second_to_first->second};
    } else if (options.place_views_without_transform) {
      forward = PlacedDirection(*graph, *first, *second, views_and_intrinsics, features, &second_in_first);
      backward = PlacedDirection(*graph, *second, *first, views_and_intrinsics, features, &first_in_second);
      if (!forward && !backward) continue;
    } else {
      continue;
    }

    ViewGraphEdge* graph_edge = graph->MutableEdge(edge.pair.first, edge.pair.second);
    ++report.num_edges;
    report.num_matches += graph_edge->matches.size();
    std::vector<FeatureMatch> kept;
    kept.reserve(graph_edge->matches.size());
    for (const FeatureMatch& match : graph_edge->matches) {
      const std::optional<bool> forward_off =
          forward ? Contradicts(*first, match.i, forward->to, match.j, forward->into_to, max_angle_rad) : std::nullopt;
      const std::optional<bool> backward_off =
          backward ? Contradicts(*second, match.j, backward->to, match.i, backward->into_to, max_angle_rad)
                   : std::nullopt;
      if (forward_off || backward_off) ++report.num_tested;
      if (forward_off.value_or(false) || backward_off.value_or(false)) {
        ++report.num_dropped;
        continue;
      }
      kept.push_back(match);
    }
    graph_edge->matches = std::move(kept);
    if (graph_edge->matches.size() < options.min_matches) report.emptied.push_back(edge);
  }
  return report;
}

void LandmarkMatchCheckOptions::Check() const {
  RequireInRange(max_angle_deg, 0.0, 90.0, "LandmarkMatchCheckOptions::max_angle_deg");
}

}  // namespace sfm_pruning
