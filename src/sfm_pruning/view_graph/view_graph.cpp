#include "sfm_pruning/view_graph/view_graph.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace sfm_pruning {
namespace {

std::string PairText(IndexT a, IndexT b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

// The same correspondences seen from the other view of the pair.
std::vector<FeatureMatch> SwappedMatches(const std::vector<FeatureMatch>& matches) {
  std::vector<FeatureMatch> swapped;
  swapped.reserve(matches.size());
  for (const FeatureMatch& m : matches) swapped.push_back({m.j, m.i});
  return swapped;
}

}  // namespace

void ViewGraph::AddNode(IndexT view_id) {
  nodes_.insert(view_id);
  incident_[view_id];  // every node has an (possibly empty) incidence set
}

ViewGraphEdge& ViewGraph::AddEdge(IndexT a, IndexT b, const std::vector<FeatureMatch>& matches,
                                  const RelativePose& pose_a_to_b) {
  if (a == b) throw std::invalid_argument("ViewGraph::AddEdge: self-loop on view " + std::to_string(a));
  ViewGraphEdge edge;
  edge.weight = static_cast<double>(matches.size());
  if (a < b) {
    edge.matches = matches;
    edge.relative_pose = pose_a_to_b;
  } else {
    edge.matches = SwappedMatches(matches);
    edge.relative_pose = pose_a_to_b.Inverse();
  }
  return AddEdge(MakeViewPair(a, b), std::move(edge));
}

ViewGraphEdge& ViewGraph::AddEdge(const ViewPair& pair, ViewGraphEdge edge) {
  if (pair.first >= pair.second) {
    throw std::invalid_argument("ViewGraph::AddEdge: pair " + PairText(pair.first, pair.second) +
                                " is not ordered first < second");
  }
  AddNode(pair.first);
  AddNode(pair.second);
  incident_[pair.first].insert(pair.second);
  incident_[pair.second].insert(pair.first);
  ViewGraphEdge& stored = edges_[pair];
  stored = std::move(edge);
  return stored;
}

void ViewGraph::RemoveNodes(const std::vector<IndexT>& view_ids) {
  for (IndexT id : view_ids) {
    auto it = incident_.find(id);
    if (it == incident_.end()) continue;
    for (IndexT other : it->second) {
      edges_.erase(MakeViewPair(id, other));
      incident_[other].erase(id);
    }
    incident_.erase(it);
    nodes_.erase(id);
  }
}

size_t ViewGraph::NumValidEdges() const {
  size_t count = 0;
  ForEachValidEdge([&count](const ViewPair&, const ViewGraphEdge&) { ++count; });
  return count;
}

const ViewGraphEdge* ViewGraph::FindEdge(IndexT a, IndexT b) const {
  const auto it = edges_.find(MakeViewPair(a, b));
  return it == edges_.end() ? nullptr : &it->second;
}

ViewGraphEdge* ViewGraph::MutableEdge(IndexT a, IndexT b) {
  const auto it = edges_.find(MakeViewPair(a, b));
  return it == edges_.end() ? nullptr : &it->second;
}

bool ViewGraph::HasValidEdge(IndexT a, IndexT b) const {
  const ViewGraphEdge* edge = FindEdge(a, b);
  return edge != nullptr && edge->is_valid;
}

std::vector<ViewPair> ViewGraph::ValidEdgePairs() const {
  std::vector<ViewPair> pairs;
  ForEachValidEdge([&pairs](const ViewPair& pair, const ViewGraphEdge&) { pairs.push_back(pair); });
  return pairs;
}

std::vector<IndexT> ViewGraph::ValidNeighbors(IndexT view_id) const {
  std::vector<IndexT> neighbors;
  const auto it = incident_.find(view_id);
  if (it == incident_.end()) return neighbors;
  for (IndexT other : it->second) {  // std::set: increasing ids
    if (HasValidEdge(view_id, other)) neighbors.push_back(other);
  }
  return neighbors;
}

std::map<IndexT, std::vector<IndexT>> ViewGraph::ValidAdjacency() const {
  std::map<IndexT, std::vector<IndexT>> adjacency;
  for (IndexT id : nodes_) adjacency[id];
  // Edges arrive in ViewPair order, so both lists stay sorted: for a node v, the partners
  // smaller than v come first (as `first` of earlier pairs), then the larger ones in order.
  ForEachValidEdge([&adjacency](const ViewPair& pair, const ViewGraphEdge&) {
    adjacency[pair.first].push_back(pair.second);
    adjacency[pair.second].push_back(pair.first);
  });
  return adjacency;
}

double ViewGraph::WeightedDegree(IndexT view_id) const {
  double degree = 0.0;
  for (IndexT other : ValidNeighbors(view_id)) degree += FindEdge(view_id, other)->weight;
  return degree;
}

RelativePose ViewGraph::OrientedRelativePose(IndexT a, IndexT b) const {
  const ViewGraphEdge* edge = FindEdge(a, b);
  if (edge == nullptr) throw std::out_of_range("ViewGraph: no edge " + PairText(a, b));
  return a < b ? edge->relative_pose : edge->relative_pose.Inverse();
}

std::vector<FeatureMatch> ViewGraph::OrientedMatches(IndexT a, IndexT b) const {
  const ViewGraphEdge* edge = FindEdge(a, b);
  if (edge == nullptr) throw std::out_of_range("ViewGraph: no edge " + PairText(a, b));
  return a < b ? edge->matches : SwappedMatches(edge->matches);
}

ViewGraph ViewGraph::InducedSubgraph(const std::set<IndexT>& view_ids) const {
  ViewGraph subgraph;
  for (IndexT id : view_ids) {
    if (HasNode(id)) subgraph.AddNode(id);
  }
  for (const auto& [pair, edge] : edges_) {
    if (view_ids.count(pair.first) > 0 && view_ids.count(pair.second) > 0) {
      subgraph.AddEdge(pair, edge);
    }
  }
  return subgraph;
}

bool ViewGraph::InvalidateEdge(IndexT a, IndexT b, const EdgeInvalidation& why) {
  ViewGraphEdge* edge = MutableEdge(a, b);
  if (edge == nullptr) throw std::out_of_range("ViewGraph: no edge " + PairText(a, b));
  if (!edge->is_valid) return false;
  edge->is_valid = false;
  edge->invalidation = why;
  return true;
}

}  // namespace sfm_pruning
