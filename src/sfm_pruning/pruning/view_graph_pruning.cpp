#include "sfm_pruning/pruning/view_graph_pruning.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

  // 2. Inter-subgraph pruning of every connected pair.
  start = std::chrono::steady_clock::now();
  const std::vector<AcceptedSubgraph>& accepted = out.partition.accepted;
  std::map<IndexT, int> subgraph_of;
  for (size_t k = 0; k < accepted.size(); ++k) {
    for (IndexT view : accepted[k].solution.view_ids) subgraph_of[view] = static_cast<int>(k);
  }
  std::set<std::pair<int, int>> connected;
  graph->ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    const auto a = subgraph_of.find(pair.first);
    const auto b = subgraph_of.find(pair.second);
    if (a == subgraph_of.end() || b == subgraph_of.end() || a->second == b->second) return;
    connected.emplace(std::min(a->second, b->second), std::max(a->second, b->second));
  });
  size_t done = 0;
  for (const auto& [k1, k2] : connected) {
    ReportProgress(progress, "inter-subgraph pruning", done++, connected.size());
    const SubgraphSolution& s1 = accepted[static_cast<size_t>(k1)].solution;
    const SubgraphSolution& s2 = accepted[static_cast<size_t>(k2)].solution;
    SubgraphAlignmentOptions alignment_options = options.alignment;
    const size_t num_edges = ConnectingEdges(*graph, s1.view_ids, s2.view_ids).size();
    if (options.max_sample_size > 0 &&
        alignment_options.sample_fraction * static_cast<double>(num_edges) >=
            static_cast<double>(options.max_sample_size + 1)) {
      alignment_options.sample_fraction =
          (static_cast<double>(options.max_sample_size) + 0.5) / static_cast<double>(num_edges);
    }
    const SubgraphAlignmentResult alignment =
        AlignSubgraphPair(*graph, s1, s2, views_and_intrinsics, features, alignment_options);
    SubgraphPairReport pair_report;
    pair_report.k1 = k1;
    pair_report.k2 = k2;
    pair_report.status = alignment.status;
    pair_report.num_edges = alignment.edges.size();
    pair_report.num_voting_edges = alignment.num_voting_edges;
    pair_report.beta = alignment.beta;
    pair_report.hypotheses = alignment.hypotheses;
    pair_report.selected_hypothesis = alignment.selected_hypothesis;
    for (const InterSubgraphEdgeDecision& decision : alignment.edges) {
      if (decision.kept) continue;
      const EdgeInvalidation why = InterSubgraphInvalidation(decision, alignment_options);
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
  ReportProgress(progress, "inter-subgraph pruning", connected.size(), connected.size());
  out.timings.push_back({"inter-subgraph pruning", SecondsSince(start)});
  out.num_output_edges = graph->NumValidEdges();
  out.total_seconds = SecondsSince(total_start);
}

void PrunedGlobalEngineOptions::SetSeedAndThreads(uint64_t seed, int num_threads) {
  engine.seed = seed;
  engine.num_threads = num_threads;
  pruning.partition.engine.seed = seed;
  pruning.partition.engine.num_threads = num_threads;
  pruning.partition.louvain.seed = seed;
  pruning.alignment.seed = seed;
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
