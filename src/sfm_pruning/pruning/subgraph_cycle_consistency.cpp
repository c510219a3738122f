#include "sfm_pruning/pruning/subgraph_cycle_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/view_graph/union_find.hpp"

namespace sfm_pruning {
namespace {

// The link's transform from `from`'s frame into `into`'s (one of its two ends each).
Similarity3 TransformInto(const SubgraphLink& link, int into) {
  return into == link.k1 ? link.k2_to_k1 : link.k2_to_k1.Inverse();
}

// MoreTrustedLink, and the earlier link on a tie.
bool MoreTrusted(const std::vector<SubgraphLink>& links, size_t a, size_t b) {
  if (MoreTrustedLink(links[a], links[b])) return true;
  if (MoreTrustedLink(links[b], links[a])) return false;
  return a < b;
}

// A cycle as a canonical key: rotated to start at its smallest subgraph, then in the direction
// whose second element is the smaller.
std::vector<int> CanonicalCycle(std::vector<int> cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  if (cycle.size() > 2 && cycle.back() < cycle[1]) std::reverse(cycle.begin() + 1, cycle.end());
  return cycle;
}

struct Forest {
  ForestAdjacency adjacent;
  std::vector<size_t> outside;  // eligible links not in the forest, most trusted first
};

Forest MaximumSpanningForest(const std::vector<SubgraphLink>& links, const std::vector<size_t>& eligible,
                             size_t num_subgraphs) {
  std::vector<size_t> order = eligible;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return MoreTrusted(links, a, b); });
  Forest forest;
  forest.adjacent.resize(num_subgraphs);
  UnionFind<size_t> sets(num_subgraphs);
  for (size_t l : order) {
    const auto a = static_cast<size_t>(links[l].k1);
    const auto b = static_cast<size_t>(links[l].k2);
    if (sets.Union(a, b)) {
      forest.adjacent[a].push_back({links[l].k2, l});
      forest.adjacent[b].push_back({links[l].k1, l});
    } else {
      forest.outside.push_back(l);
    }
  }
  return forest;
}

}  // namespace

std::pair<std::vector<int>, std::vector<size_t>> ForestPath(const ForestAdjacency& forest, int from, int to) {
  std::vector<int> previous(forest.size(), -1);
  std::vector<size_t> via(forest.size(), 0);
  std::deque<int> queue{from};
  previous[static_cast<size_t>(from)] = from;
  while (!queue.empty() && previous[static_cast<size_t>(to)] < 0) {
    const int node = queue.front();
    queue.pop_front();
    for (const auto& [next, link] : forest[static_cast<size_t>(node)]) {
      if (previous[static_cast<size_t>(next)] >= 0) continue;
      previous[static_cast<size_t>(next)] = node;
      via[static_cast<size_t>(next)] = link;
      queue.push_back(next);
    }
  }
  std::vector<int> nodes;
  std::vector<size_t> path_links;
  if (previous[static_cast<size_t>(to)] < 0) return {nodes, path_links};
  for (int node = to; node != from; node = previous[static_cast<size_t>(node)]) {
    nodes.push_back(node);
    path_links.push_back(via[static_cast<size_t>(node)]);
  }
  nodes.push_back(from);
  std::reverse(nodes.begin(), nodes.end());
  std::reverse(path_links.begin(), path_links.end());
  return {nodes, path_links};
}

size_t CycleLoopFactor(size_t length) { return std::max<size_t>(1, (length - 1) / 2); }

CycleBounds WidenedCycleBounds(size_t loop_factor, const SubgraphLoopOptions& options) {
  const double factor = static_cast<double>(loop_factor);
  return {options.max_rotation_deg * factor, std::pow(options.max_scale_ratio, factor),
          options.max_translation_fraction * factor};
}

SubgraphCycle MeasureSubgraphCycle(const std::vector<int>& subgraphs, const std::vector<Similarity3>& to_previous,
                                   const std::vector<SubgraphFrame>& frames, const SubgraphLoopOptions& options) {
  SubgraphCycle cycle;
  cycle.subgraphs = subgraphs;
  const size_t length = subgraphs.size();
  const SubgraphFrame& first = frames[static_cast<size_t>(subgraphs.front())];
  // accumulated = T_{c0 <- c(k+1)}; the centres of c1.. in c0's frame along the way.
  Similarity3 accumulated;
  std::vector<Eigen::Vector3d> centres{first.center};
  for (size_t k = 0; k < length; ++k) {
    accumulated = accumulated.Compose(to_previous[k]);
    if (k + 1 < length) centres.push_back(accumulated.Apply(frames[static_cast<size_t>(subgraphs[k + 1])].center));
  }
  double sides = 0.0;
  for (size_t k = 0; k < length; ++k) sides += (centres[k] - centres[(k + 1) % length]).norm();
  const double reference = std::max(sides / static_cast<double>(length), first.radius);
  cycle.rotation_deg = RadToDeg(RotationAngleBetween(accumulated.rotation, Eigen::Matrix3d::Identity()));
  cycle.scale_ratio = accumulated.scale >= 1.0 ? accumulated.scale : 1.0 / accumulated.scale;
  const double displacement = (accumulated.Apply(first.center) - first.center).norm();
  cycle.translation_fraction = reference > 0.0 ? displacement / reference : 0.0;
  cycle.loop_factor = CycleLoopFactor(length);
  const CycleBounds bounds = WidenedCycleBounds(cycle.loop_factor, options);
  cycle.consistent = cycle.rotation_deg <= bounds.rotation_deg && cycle.scale_ratio <= bounds.scale_ratio &&
                     cycle.translation_fraction <= bounds.translation_fraction;
  return cycle;
}

void RejectCycleInconsistentLinks(const std::vector<SubgraphLink>& links, const std::vector<SubgraphFrame>& frames,
                                  const SubgraphLoopOptions& options, std::vector<bool>* active,
                                  SubgraphLoopResult* result) {
  if (!options.enabled || options.max_cycle_length < 4) return;
  std::set<std::vector<int>> closing;  // consistent cycles already reported
  bool cut = true;
  while (cut) {
    cut = false;
    std::vector<size_t> eligible;
    std::set<std::pair<int, int>> present;
    for (size_t l = 0; l < links.size(); ++l) {
      if (!(*active)[l]) continue;
      eligible.push_back(l);
      present.insert({links[l].k1, links[l].k2});
    }
    const Forest forest = MaximumSpanningForest(links, eligible, frames.size());
    for (size_t outside : forest.outside) {
      auto [nodes, cycle_links] = ForestPath(forest.adjacent, links[outside].k1, links[outside].k2);
      const size_t length = nodes.size();
      if (length < 4 || length > options.max_cycle_length) continue;
      bool has_chord = false;
      for (size_t a = 0; a < length && !has_chord; ++a) {
        for (size_t b = a + 2; b < length && !has_chord; ++b) {
          if (a == 0 && b + 1 == length) continue;  // that one is the closing link itself
          has_chord = present.count({std::min(nodes[a], nodes[b]), std::max(nodes[a], nodes[b])}) > 0;
        }
      }
      if (has_chord) continue;
      const std::vector<int> key = CanonicalCycle(nodes);
      if (closing.count(key)) continue;
      cycle_links.push_back(outside);  // c(l-1) -> c0
      std::vector<Similarity3> to_previous;
      for (size_t k = 0; k < length; ++k) {
        to_previous.push_back(TransformInto(links[cycle_links[k]], nodes[k]));
      }
      result->cycles.push_back(MeasureSubgraphCycle(nodes, to_previous, frames, options));
      if (result->cycles.back().consistent) {
        closing.insert(key);
        continue;
      }
      size_t weakest = cycle_links.front();
      for (size_t l : cycle_links) {
        if (MoreTrusted(links, weakest, l)) weakest = l;
      }
      (*active)[weakest] = false;
      result->rejected.push_back({weakest, 1, 0, static_cast<int>(result->cycles.size()) - 1});
      cut = true;
      break;
    }
  }
}

}  // namespace sfm_pruning
