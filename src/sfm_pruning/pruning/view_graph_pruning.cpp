#include "sfm_pruning/pruning/view_graph_pruning.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/util/parallel_for.hpp"
#include "sfm_pruning/util/statistics.hpp"
#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Pairs (k1 < k2) of accepted subgraphs joined by at least one valid edge, in increasing order.
std::vector<std::pair<int, int>> ConnectedSubgraphPairs(const ViewGraph& graph,
                                                        const std::vector<AcceptedSubgraph>& accepted) {
  std::map<IndexT, int> subgraph_of;
  for (size_t k = 0; k < accepted.size(); ++k) {
    for (IndexT view : accepted[k].solution.view_ids) subgraph_of[view] = static_cast<int>(k);
  }
  std::set<std::pair<int, int>> connected;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    const auto a = subgraph_of.find(pair.first);
    const auto b = subgraph_of.find(pair.second);
    if (a == subgraph_of.end() || b == subgraph_of.end() || a->second == b->second) return;
    connected.emplace(std::min(a->second, b->second), std::max(a->second, b->second));
  });
  return {connected.begin(), connected.end()};
}

// The alignment options of a pair with `num_edges` connecting edges: the sample fraction lowered
// so that a sample holds at most max_sample_size edges (ViewGraphPruningOptions).
SubgraphAlignmentOptions PairAlignmentOptions(const ViewGraphPruningOptions& options, size_t num_edges) {
  SubgraphAlignmentOptions alignment = options.alignment;
  if (options.max_sample_size > 0 && alignment.sample_fraction * static_cast<double>(num_edges) >=
                                         static_cast<double>(options.max_sample_size + 1)) {
    alignment.sample_fraction = (static_cast<double>(options.max_sample_size) + 0.5) / static_cast<double>(num_edges);
  }
  return alignment;
}

// Mean camera centre and median distance of the centres to it, in the subgraph's frame.
SubgraphFrame FrameOfSubgraph(const SubgraphSolution& solution) {
  SubgraphFrame frame;
  if (solution.poses.empty()) return frame;
  frame.centre = SubgraphMeanCentre(solution);  // not SubgraphMeanPose: its rotation mean is unused here
  std::vector<double> distances;
  for (const auto& [view_id, pose] : solution.poses) distances.push_back((pose.center - frame.centre).norm());
  frame.radius = Median(std::move(distances));
  return frame;
}

}  // namespace

void PruneViewGraph(const ViewGraphPruningOptions& options, ViewGraph* graph, const SfmData& views_and_intrinsics,
                    const FeaturesPerView& features, ViewGraphPruningReport* report,
                    const ProgressCallback& progress) {
  const auto total_start = std::chrono::steady_clock::now();
  ViewGraphPruningReport local;
  ViewGraphPruningReport& out = report != nullptr ? *report : local;
  out = ViewGraphPruningReport();
  out.num_input_edges = graph->NumValidEdges();

  // 1. Recursive partition of the largest component.
  auto start = std::chrono::steady_clock::now();
  const NodeGroup component = LargestComponent(*graph);
  const ViewGraph component_graph = graph->InducedSubgraph(std::set<IndexT>(component.begin(), component.end()));
  out.partition = PartitionViewGraph(options.partition, component_graph, views_and_intrinsics, features, progress);
  out.timings.push_back({"subgraph partition", SecondsSince(start)});

  // 2. Alignment of every connected pair of subgraphs (decisions only, the graph is unchanged).
  start = std::chrono::steady_clock::now();
  const std::vector<AcceptedSubgraph>& accepted = out.partition.accepted;
  const std::vector<std::pair<int, int>> pairs = ConnectedSubgraphPairs(*graph, accepted);
  std::vector<SubgraphAlignmentResult> alignments(pairs.size());
  ParallelFor(
      pairs.size(), options.num_threads,
      [&](size_t p) {
        const SubgraphSolution& s1 = accepted[static_cast<size_t>(pairs[p].first)].solution;
        const SubgraphSolution& s2 = accepted[static_cast<size_t>(pairs[p].second)].solution;
        const size_t num_edges = ConnectingEdges(*graph, s1.view_ids, s2.view_ids).size();
        alignments[p] = AlignSubgraphPair(*graph, s1, s2, views_and_intrinsics, features,
                                          PairAlignmentOptions(options, num_edges));
      },
      progress, "inter-subgraph pruning");

  // 3. Loops of aligned pairs: a pair whose frame transform breaks them is cut whole.
  std::vector<SubgraphLink> links;
  std::vector<size_t> pair_of_link;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const SubgraphAlignmentResult& alignment = alignments[p];
    // A transform no connecting edge agrees with is no evidence about the loops (real street: two
    // such pairs, fitted on samples of doppelgangers, closed a triangle with each other).
    if (!alignment.has_frame_transform || alignment.consensus_size == 0) continue;
    const AlignmentHypothesis& selected = alignment.hypotheses[static_cast<size_t>(alignment.selected_hypothesis)];
    links.push_back({pairs[p].first, pairs[p].second, alignment.k2_to_k1, alignment.consensus_size, selected.Coverage()});
    pair_of_link.push_back(p);
  }
  std::vector<SubgraphFrame> frames;
  for (const AcceptedSubgraph& subgraph : accepted) frames.push_back(FrameOfSubgraph(subgraph.solution));
  const SubgraphLoopResult loops = FindLoopInconsistentLinks(links, frames, options.loops);
  out.triangles = loops.triangles;
  out.cycles = loops.cycles;
  std::map<size_t, RejectedLink> rejected_pairs;
  for (const RejectedLink& rejected : loops.rejected) rejected_pairs[pair_of_link[rejected.link]] = rejected;
  std::map<size_t, size_t> link_of_pair;
  for (size_t l = 0; l < pair_of_link.size(); ++l) link_of_pair[pair_of_link[l]] = l;

  // 4. The decisions applied to the graph.
  for (size_t p = 0; p < pairs.size(); ++p) {
    const auto [k1, k2] = pairs[p];
    SubgraphAlignmentResult& alignment = alignments[p];
    const auto rejected = rejected_pairs.find(p);
    if (rejected != rejected_pairs.end()) {
      for (InterSubgraphEdgeDecision& decision : alignment.edges) {
        decision.kept = false;
        decision.verdict = InterSubgraphVerdict::kLoopInconsistent;
      }
    }
    SubgraphPairReport pair_report;
    pair_report.k1 = k1;
    pair_report.k2 = k2;
    pair_report.status = alignment.status;
    pair_report.num_edges = alignment.edges.size();
    pair_report.num_voting_edges = alignment.num_voting_edges;
    pair_report.beta = alignment.beta;
    pair_report.hypotheses = alignment.hypotheses;
    pair_report.selected_hypothesis = alignment.selected_hypothesis;
    pair_report.has_frame_transform = alignment.has_frame_transform;
    pair_report.k2_to_k1 = alignment.k2_to_k1;
    const auto link = link_of_pair.find(p);
    if (link != link_of_pair.end()) {
      pair_report.consistent_triangles = loops.consistent_triangles[link->second];
      pair_report.inconsistent_triangles = loops.inconsistent_triangles[link->second];
    }
    pair_report.rejected_by_loops = rejected != rejected_pairs.end();
    pair_report.rejected_by_cycle = pair_report.rejected_by_loops ? rejected->second.cycle : -1;
    for (const InterSubgraphEdgeDecision& decision : alignment.edges) {
      if (decision.kept) continue;
      const EdgeInvalidation why =
          pair_report.rejected_by_loops
              ? EdgeInvalidation{EdgeInvalidReason::kSubgraphLoopInconsistent,
                                 static_cast<double>(rejected->second.inconsistent_triangles),
                                 static_cast<double>(rejected->second.consistent_triangles)}
              : InterSubgraphInvalidation(decision, options.alignment);
      if (!graph->InvalidateEdge(decision.placement.view_i, decision.placement.view_j, why)) continue;
      RemovedEdge removed;
      removed.pair = decision.placement.view_i < decision.placement.view_j
                         ? ViewPair{decision.placement.view_i, decision.placement.view_j}
                         : ViewPair{decision.placement.view_j, decision.placement.view_i};
      removed.k1 = k1;
      removed.k2 = k2;
      removed.verdict = decision.verdict;
      removed.invalidation = why;
      out.removed_edges.push_back(removed);
      ++pair_report.num_removed_edges;
    }
    out.pairs.push_back(pair_report);
  }
  out.timings.push_back({"inter-subgraph pruning", SecondsSince(start)});
  out.num_output_edges = graph->NumValidEdges();
  out.total_seconds = SecondsSince(total_start);
}

void PrunedGlobalEngineOptions::SetSeedAndThreads(uint64_t seed, int num_threads) {
  engine.seed = seed;
  engine.num_threads = num_threads;
  pruning.partition.engine.seed = seed;
  // Communities in parallel, each engine run on one thread: the partition is then the same for
  // any thread count (a multi-threaded Ceres sums in a thread-dependent order).
  pruning.partition.engine.num_threads = 1;
  pruning.partition.num_threads = num_threads;
  pruning.partition.louvain.seed = seed;
  pruning.alignment.seed = seed;
  pruning.num_threads = num_threads;
}

void RunPrunedGlobalEngine(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                           const SfmData& views_and_intrinsics, const FeaturesPerView& features, SfmData* out,
                           PrunedGlobalEngineReport* report, const ProgressCallback& progress) {
  PrunedGlobalEngineReport local;
  PrunedGlobalEngineReport& result = report != nullptr ? *report : local;
  ViewGraph pruned = graph;
  PruneViewGraph(options.pruning, &pruned, views_and_intrinsics, features, &result.pruning, progress);
  RunGlobalEngine(options.engine, pruned, views_and_intrinsics, features, out, &result.engine, progress);
}

}  // namespace sfm_pruning
