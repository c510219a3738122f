#include "sfm_pruning/global/match_star_tracks.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace sfm_pruning {

std::vector<Track> BuildMatchStarTracks(const ViewGraph& graph, size_t min_track_length) {
  using Node = std::pair<IndexT, IndexT>;  // (view id, feature id)
  std::map<Node, std::vector<Node>> matched_to;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    for (const FeatureMatch& match : edge.matches) {
      matched_to[{pair.first, match.i}].emplace_back(pair.second, match.j);
      matched_to[{pair.second, match.j}].emplace_back(pair.first, match.i);
    }
  });
  std::vector<Track> stars;
  for (auto& [centre, neighbours] : matched_to) {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    Track star{{centre.first, centre.second}};
    for (size_t k = 0; k < neighbours.size(); ++k) {
      const IndexT view_id = neighbours[k].first;
      const bool ambiguous = (k > 0 && neighbours[k - 1].first == view_id) ||
                             (k + 1 < neighbours.size() && neighbours[k + 1].first == view_id);
      if (!ambiguous && view_id != centre.first) star.emplace(view_id, neighbours[k].second);
    }
    if (star.size() >= min_track_length) stars.push_back(std::move(star));
  }
  std::sort(stars.begin(), stars.end());
  stars.erase(std::unique(stars.begin(), stars.end()), stars.end());
  return stars;
}

}  // namespace sfm_pruning
