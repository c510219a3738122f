#include "sfm_pruning/global/tracks.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "sfm_pruning/view_graph/union_find.hpp"

namespace sfm_pruning {
namespace {

using TrackNode = std::pair<IndexT, IndexT>;  // (view id, feature id)

// Every (view, feature) that takes part in a valid match, sorted and unique: the dense index of a
// node is its rank, so component order and tie-breaks follow (view, feature) order.
std::vector<TrackNode> CollectTrackNodes(const ViewGraph& graph) {
  std::vector<TrackNode> nodes;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    for (const FeatureMatch& match : edge.matches) {
      nodes.emplace_back(pair.first, match.i);
      nodes.emplace_back(pair.second, match.j);
    }
  });
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

size_t DenseIndexOf(const std::vector<TrackNode>& nodes, const TrackNode& node) {
  return static_cast<size_t>(std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin());
}

// Components of the match graph as lists of dense node indices. Components are ordered by their
// smallest node and each list is increasing (nodes are visited in increasing order).
std::vector<std::vector<size_t>> MatchComponents(const ViewGraph& graph, const std::vector<TrackNode>& nodes) {
  UnionFind<size_t> sets(nodes.size());
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    for (const FeatureMatch& match : edge.matches) {
      sets.Union(DenseIndexOf(nodes, {pair.first, match.i}), DenseIndexOf(nodes, {pair.second, match.j}));
    }
  });
  std::vector<std::vector<size_t>> components;
  std::vector<size_t> component_of_root(nodes.size(), nodes.size());
  for (size_t node = 0; node < nodes.size(); ++node) {
    size_t& component = component_of_root[sets.Find(node)];
    if (component == nodes.size()) {
      component = components.size();
      components.emplace_back();
    }
    components[component].push_back(node);
  }
  return components;
}

// Nodes are sorted by view, so a view repeated inside a component shows up as two neighbours.
bool HasTwoFeaturesInOneView(const std::vector<size_t>& component, const std::vector<TrackNode>& nodes) {
  for (size_t k = 1; k < component.size(); ++k) {
    if (nodes[component[k]].first == nodes[component[k - 1]].first) return true;
  }
  return false;
}

// Indices of the tracks that survive the caps, in increasing order (so ids stay sorted).
std::vector<size_t> SelectCappedTracks(const std::vector<Track>& tracks, const TrackBuildingOptions& options) {
  std::vector<size_t> order(tracks.size());
  std::iota(order.begin(), order.end(), size_t{0});
  // Longest first; stable sort keeps the smaller id first among equal lengths.
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return tracks[a].size() > tracks[b].size(); });
  std::map<IndexT, size_t> kept_per_view;
  std::vector<size_t> selected;
  for (const size_t index : order) {
    if (options.max_num_tracks > 0 && selected.size() >= options.max_num_tracks) break;
    if (options.max_tracks_per_view > 0) {
      const bool some_view_needs_it = std::any_of(tracks[index].begin(), tracks[index].end(), [&](const auto& entry) {
        return kept_per_view[entry.first] < options.max_tracks_per_view;
      });
      if (!some_view_needs_it) continue;
    }
    for (const auto& [view_id, feature_id] : tracks[index]) ++kept_per_view[view_id];
    selected.push_back(index);
  }
  std::sort(selected.begin(), selected.end());
  return selected;
}

}  // namespace

TrackBuildingResult BuildTracks(const ViewGraph& graph, const TrackBuildingOptions& options) {
  TrackBuildingResult result;
  const std::vector<TrackNode> nodes = CollectTrackNodes(graph);
  const std::vector<std::vector<size_t>> components = MatchComponents(graph, nodes);
  result.num_candidate_tracks = components.size();

  std::vector<Track> tracks;
  for (const std::vector<size_t>& component : components) {
    if (HasTwoFeaturesInOneView(component, nodes)) {
      ++result.num_conflicting_tracks;
      continue;
    }
    if (component.size() < options.min_track_length) {
      ++result.num_short_tracks;
      continue;
    }
    Track track;
    for (const size_t node : component) track.emplace(nodes[node].first, nodes[node].second);
    tracks.push_back(std::move(track));
  }

  if (options.max_tracks_per_view == 0 && options.max_num_tracks == 0) {
    result.tracks = std::move(tracks);
    return result;
  }
  const std::vector<size_t> selected = SelectCappedTracks(tracks, options);
  result.num_capped_tracks = tracks.size() - selected.size();
  result.tracks.reserve(selected.size());
  for (const size_t index : selected) result.tracks.push_back(std::move(tracks[index]));
  return result;
}

void TrackBuildingOptions::Check() const {
  // Every track has two views (a match joins two), so a smaller minimum would mean nothing. The caps
  // take any count (0: no cap).
  RequireAtLeast<size_t>(min_track_length, 2, "TrackBuildingOptions::min_track_length");
}

}  // namespace sfm_pruning
