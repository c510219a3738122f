#include "sfm_pruning/pruning/trusted_link_forest.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "sfm_pruning/pruning/subgraph_cycle_consistency.hpp"
#include "sfm_pruning/view_graph/union_find.hpp"

namespace sfm_pruning {
namespace {

// The forest grown so far: per subgraph, (neighbour, pair) of its forest pairs.
class GrowingForest {
 public:
  explicit GrowingForest(size_t num_subgraphs) : adjacent_(num_subgraphs), sets_(num_subgraphs) {}

  bool Connected(int a, int b) { return sets_.Connected(static_cast<size_t>(a), static_cast<size_t>(b)); }

  void Add(int a, int b, size_t pair) {
    sets_.Union(static_cast<size_t>(a), static_cast<size_t>(b));
    adjacent_[static_cast<size_t>(a)].push_back({b, pair});
    adjacent_[static_cast<size_t>(b)].push_back({a, pair});
  }

  // The subgraphs from `from` to `to` along the forest and the pairs between them (connected ends).
  std::pair<std::vector<int>, std::vector<size_t>> Path(int from, int to) const {
    return ForestPath(adjacent_, from, to);
  }

 private:
  ForestAdjacency adjacent_;
  UnionFind<size_t> sets_;
};

// The pair's transform from `from`'s frame into `into`'s (one of its two ends each).
Similarity3 TransformInto(const SubgraphPairLink& pair, int into) {
  return into == pair.k1 ? pair.k2_to_k1 : pair.k2_to_k1.Inverse();
}

// SubgraphLoopOptions::verify_along_verified_paths: a second look at the redundant pairs without a
// transform of their own that the forest could not verify (a pair on their forest path has no
// transform either). The shortest path of verified transforms between their subgraphs (forest pairs
// with a transform, and pairs that closed their cycle) stands in for the forest path, and `check`
// judges the pair's edges against the transform chained along it. Judged in the forest's order
// against a fixed set of verified pairs, so the result does not depend on which pair comes first.
void VerifyAlongVerifiedPaths(const std::vector<SubgraphPairLink>& pairs, size_t num_subgraphs,
                              const std::vector<size_t>& order, const ForestTransformCheck& check,
                              TrustedForestResult* result) {
  ForestAdjacency verified(num_subgraphs);
  for (size_t q = 0; q < pairs.size(); ++q) {
    const LinkDecision decision = result->decisions[q];
    if (!pairs[q].has_transform || (decision != LinkDecision::kForest && decision != LinkDecision::kClosesCycle)) {
      continue;
    }
    verified[static_cast<size_t>(pairs[q].k1)].push_back({pairs[q].k2, q});
    verified[static_cast<size_t>(pairs[q].k2)].push_back({pairs[q].k1, q});
  }
  for (size_t p : order) {
    const SubgraphPairLink& pair = pairs[p];
    const LinkDecision decision = result->decisions[p];
    if (pair.has_transform ||
        (decision != LinkDecision::kRedundantUnverified && decision != LinkDecision::kKeptUnverified)) {
      continue;
    }
    const auto [nodes, path] = ForestPath(verified, pair.k1, pair.k2);
    if (nodes.empty()) continue;
    ChainedTransform chained;
    chained.loop_factor = CycleLoopFactor(nodes.size());
    for (size_t k = 0; k < path.size(); ++k) {
      chained.k2_to_k1 = chained.k2_to_k1.Compose(TransformInto(pairs[path[k]], nodes[k]));
    }
    const std::optional<bool> agrees = check(p, chained);
    if (agrees) result->decisions[p] = *agrees ? LinkDecision::kAgreesWithForest : LinkDecision::kContradictsForest;
  }
}

}  // namespace

const char* LinkDecisionName(LinkDecision decision) {
  switch (decision) {
    case LinkDecision::kForest: return "forest";
    case LinkDecision::kClosesCycle: return "closes_cycle";
    case LinkDecision::kBreaksCycle: return "breaks_cycle";
    case LinkDecision::kRedundantUnverified: return "redundant_unverified";
    case LinkDecision::kKeptUnverified: return "kept_unverified";
    case LinkDecision::kAgreesWithForest: return "agrees_with_forest";
    case LinkDecision::kContradictsForest: return "contradicts_forest";
  }
  return "unknown";
}

TrustedForestResult SelectLinksByTrustedForest(const std::vector<SubgraphPairLink>& pairs,
                                               const std::vector<SubgraphFrame>& frames,
                                               const SubgraphLoopOptions& options,
                                               const ForestTransformCheck& check_against_forest) {
  TrustedForestResult result;
  result.decisions.assign(pairs.size(), LinkDecision::kForest);
  result.cycle_of.assign(pairs.size(), -1);
  std::vector<size_t> order(pairs.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const bool a_enough = pairs[a].num_edges >= options.min_edges_for_trust;
    const bool b_enough = pairs[b].num_edges >= options.min_edges_for_trust;
    if (a_enough != b_enough) return a_enough;
    if (pairs[a].capture_linked != pairs[b].capture_linked) return pairs[a].capture_linked;
    if (pairs[a].trust != pairs[b].trust) return pairs[a].trust > pairs[b].trust;
    return pairs[a].support > pairs[b].support;
  });
  GrowingForest forest(frames.size());
  for (size_t p : order) {
    const SubgraphPairLink& pair = pairs[p];
    if (!forest.Connected(pair.k1, pair.k2)) {
      forest.Add(pair.k1, pair.k2, p);
      continue;
    }
    // The cycle c0 = k1 -> ... (forest) ... -> c(l-1) = k2 -> k1 (this pair).
    auto [nodes, cycle_pairs] = forest.Path(pair.k1, pair.k2);
    cycle_pairs.push_back(p);
    const bool verifiable = std::all_of(cycle_pairs.begin(), cycle_pairs.end(),
                                        [&](size_t q) { return pairs[q].has_transform; });
    if (!verifiable) {
      const bool vouched =
          pair.trust >= options.min_unverified_trust &&
          (pair.relative_coverage < 0.0 || pair.relative_coverage >= options.min_unverified_coverage);
      result.decisions[p] = vouched ? LinkDecision::kKeptUnverified : LinkDecision::kRedundantUnverified;
      continue;
    }
    std::vector<Similarity3> to_previous;
    for (size_t k = 0; k < nodes.size(); ++k) to_previous.push_back(TransformInto(pairs[cycle_pairs[k]], nodes[k]));
    result.cycles.push_back(MeasureSubgraphCycle(nodes, to_previous, frames, options));
    result.cycle_of[p] = static_cast<int>(result.cycles.size()) - 1;
    result.decisions[p] = result.cycles.back().consistent ? LinkDecision::kClosesCycle : LinkDecision::kBreaksCycle;
  }
  if (options.verify_along_verified_paths && check_against_forest) {
    VerifyAlongVerifiedPaths(pairs, frames.size(), order, check_against_forest, &result);
  }
  return result;
}

}  // namespace sfm_pruning
