#include "sfm_pruning/pruning/recursive_partition.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <chrono>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sfm_pruning/util/parallel_for.hpp"
#include "sfm_pruning/view_graph/distinctive_weights.hpp"
#include "sfm_pruning/view_graph/spectral_bisection.hpp"

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Nodes are processed in waves: every community Louvain produced in the previous wave is solved
// and tested in parallel (each is independent of its siblings and cousins), then the inconsistent
// ones are split, one after the other, into the next wave. PartitionViewGraph then puts the
// result into the order a one-at-a-time depth-first partition gives (Renumber), so that nothing
// downstream depends on the waves or the thread count.
class Partitioner {
 public:
  Partitioner(const RecursivePartitionOptions& options, const ViewGraph& graph, const SfmData& views_and_intrinsics,
              const FeaturesPerView& features, const CaptureOrder& capture_order, const ProgressCallback& progress)
      : options_(options),
        graph_(graph),
        views_and_intrinsics_(views_and_intrinsics),
        features_(features),
        progress_(progress) {
    // Computed once on the whole graph: a feature's match count is a property of the collection,
    // not of the community it ends up in.
    if (options_.edge_weight == RecursivePartitionOptions::EdgeWeight::kDistinctiveMatches) {
      louvain_weights_ = DistinctiveMatchWeights(graph_, FeatureDistinctiveness(graph_));
    }
    if (capture_order.Used()) WeighCaptureNeighbours(capture_order);
  }

  RecursivePartitionResult Run() {
    SubgraphNode root;
    root.view_ids.assign(graph_.Nodes().begin(), graph_.Nodes().end());
    root.num_edges = graph_.NumValidEdges();
    result_.nodes.push_back(std::move(root));
    if (result_.nodes[0].view_ids.empty()) return std::move(result_);
    std::vector<int> wave;
    if (!Split(0, &wave)) {
      // Louvain cannot split the whole graph: it is one subgraph, reconstructed as is.
      Accept(0, SubgraphStatus::kUnsplittable, Evaluate(0));
    }
    size_t processed = 1;
    while (!wave.empty()) {
      std::vector<SubgraphSolution> solutions(wave.size());
      const size_t known = result_.nodes.size();
      ProgressCallback wave_progress;
      if (progress_) {
        wave_progress = [this, processed, known](const std::string&, size_t done, size_t) {
          ReportProgress(progress_, "subgraph partition", processed + done, known);
        };
      }
      ParallelFor(
          wave.size(), options_.num_threads, [&](size_t k) { solutions[k] = Evaluate(wave[k]); }, wave_progress);
      processed += wave.size();
      std::vector<int> next_wave;
      for (size_t k = 0; k < wave.size(); ++k) Decide(wave[k], std::move(solutions[k]), &next_wave);
      wave = std::move(next_wave);
    }
    for (const SubgraphNode& node : result_.nodes) {
      if (node.solved && node.view_ids.size() >= 2) ++result_.num_engine_runs;
    }
    ReportProgress(progress_, "subgraph partition", result_.nodes.size(), result_.nodes.size());
    return std::move(result_);
  }

 private:
  // The capture-order prior (capture_order.hpp): edges between capture neighbours weigh more.
  void WeighCaptureNeighbours(const CaptureOrder& capture_order) {
    graph_.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
      // Without distinctiveness weights Louvain would use the graph's own: start from those.
      const auto weight = louvain_weights_.emplace(pair, edge.weight).first;
      if (capture_order.AreNeighbours(pair.first, pair.second)) weight->second *= capture_order.PartitionWeightFactor();
    });
  }

  // Louvain on the node's induced subgraph; appends the children to the tree and to `wave`.
  // False when Louvain returns fewer than two communities.
  bool Split(int index, std::vector<int>* wave) {
    const std::vector<IndexT>& views = result_.nodes[static_cast<size_t>(index)].view_ids;
    ViewGraph induced = graph_.InducedSubgraph(std::set<IndexT>(views.begin(), views.end()));
    if (!louvain_weights_.empty()) {
      for (const ViewPair& pair : induced.ValidEdgePairs()) {
        induced.MutableEdge(pair.first, pair.second)->weight = louvain_weights_.at(pair);
      }
    }
    LouvainResult louvain = DetectCommunitiesLouvain(induced, options_.louvain);
    // Only the root reaches Split without a failed consistency test, and it keeps Louvain's answer.
    const bool bisect = louvain.communities.size() < 2 && index != 0 && options_.bisect_unsplittable &&
                        views.size() >= 4;  // halves of two views or more: a single view has no landmarks
    if (bisect) {
      const auto [first, second] = SpectralBisection(induced);
      louvain.communities = {first, second};
      result_.nodes[static_cast<size_t>(index)].bisected = true;
    }
    if (louvain.communities.size() < 2) return false;
    std::vector<int> children;
    for (const NodeGroup& community : louvain.communities) {
      SubgraphNode child;
      child.parent = index;
      child.depth = result_.nodes[static_cast<size_t>(index)].depth + 1;
      child.view_ids = community;
      result_.nodes.push_back(std::move(child));
      children.push_back(static_cast<int>(result_.nodes.size()) - 1);
    }
    result_.nodes[static_cast<size_t>(index)].children = children;
    result_.nodes[static_cast<size_t>(index)].status = SubgraphStatus::kSplit;
    wave->insert(wave->end(), children.begin(), children.end());
    return true;
  }

  // Solves and (unless tiny) tests one node. Touches only that node: safe in parallel while the
  // tree does not grow.
  SubgraphSolution Evaluate(int index) {
    SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    const ViewGraph induced = graph_.InducedSubgraph(std::set<IndexT>(node.view_ids.begin(), node.view_ids.end()));
    node.num_edges = induced.NumValidEdges();
    SubgraphSolution solution = Solve(index, induced);
    if (node.view_ids.size() > options_.tiny_subgraph_size) Test(index, induced, solution);
    return solution;
  }

  void Decide(int index, SubgraphSolution solution, std::vector<int>* next_wave) {
    const SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    if (node.view_ids.size() <= options_.tiny_subgraph_size) {
      Accept(index, SubgraphStatus::kTiny, std::move(solution));
    } else if (node.consistency.consistent) {
      Accept(index, SubgraphStatus::kConsistent, std::move(solution));
    } else if (!options_.recursive) {
      Accept(index, SubgraphStatus::kSinglePass, std::move(solution));
    } else if (node.depth >= options_.max_depth) {
      Accept(index, SubgraphStatus::kMaxDepth, std::move(solution));
    } else if (!Split(index, next_wave)) {
      Accept(index, SubgraphStatus::kUnsplittable, std::move(solution));
    }
  }

  // Reconstructs the node's views with the GLOBAL engine; tiny fallbacks for 1–2 views.
  SubgraphSolution Solve(int index, const ViewGraph& induced) {
    const auto start = std::chrono::steady_clock::now();
    SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    node.solved = true;
    SubgraphSolution solution;
    solution.view_ids.insert(node.view_ids.begin(), node.view_ids.end());
    if (node.view_ids.size() == 1) {
      node.engine_message = "single view: identity pose";
      solution.poses.emplace(node.view_ids.front(), Pose());
    } else {
      SfmData model;
      GlobalEngineReport report;
      RunGlobalEngine(options_.engine, induced, views_and_intrinsics_, features_, &model, &report);
      node.engine_success = report.success;
      node.engine_message = report.message;
      if (report.success) {
        solution = SolutionFromModel(node.view_ids, model);
      } else if (node.view_ids.size() == 2 && induced.HasValidEdge(node.view_ids[0], node.view_ids[1])) {
        const Pose first;
        solution.poses.emplace(node.view_ids[0], first);
        solution.poses.emplace(node.view_ids[1],
                               ComposePose(first, induced.OrientedRelativePose(node.view_ids[0], node.view_ids[1])));
      }
    }
    node.num_registered = solution.poses.size();
    node.num_landmarks = solution.landmarks.size();
    node.seconds += SecondsSince(start);
    return solution;
  }

  void Test(int index, const ViewGraph& induced, const SubgraphSolution& solution) {
    const auto start = std::chrono::steady_clock::now();
    SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    node.consistency_tested = true;
    if (!node.engine_success) {
      // A community the engine cannot reconstruct is not a consistent subgraph.
      node.consistency = ConsistencyReport();
      node.consistency.consistent = false;
    } else {
      node.consistency = TestSubgraphConsistency(induced, solution, options_.consistency);
      TestBaselineRatios(induced, solution, views_and_intrinsics_, features_, options_.consistency,
                         &node.consistency);
    }
    node.seconds += SecondsSince(start);
  }

  void Accept(int index, SubgraphStatus status, SubgraphSolution solution) {
    SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    node.status = status;
    node.accepted_index = static_cast<int>(result_.accepted.size());
    result_.accepted.push_back({index, std::move(solution)});
  }

  const RecursivePartitionOptions& options_;
  const ViewGraph& graph_;
  const SfmData& views_and_intrinsics_;
  const FeaturesPerView& features_;
  const ProgressCallback& progress_;
  std::map<ViewPair, double> louvain_weights_;  // empty: Louvain uses the graph's own weights
  RecursivePartitionResult result_;
};

// Depth-first order: a node's children are numbered together when it is split, then each child's
// subtree in turn; accepted subgraphs in the order of their leaves. This is the order in which a
// sequential depth-first partition creates and accepts them.
RecursivePartitionResult Renumber(RecursivePartitionResult waves) {
  const size_t count = waves.nodes.size();
  std::vector<int> new_index(count, -1);
  std::vector<int> leaf_order;
  new_index[0] = 0;
  int next = 1;
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const int old = stack.back();
    stack.pop_back();
    const SubgraphNode& node = waves.nodes[static_cast<size_t>(old)];
    for (int child : node.children) new_index[static_cast<size_t>(child)] = next++;
    if (node.accepted_index >= 0) leaf_order.push_back(old);
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back(*child);
  }
  RecursivePartitionResult ordered;
  ordered.num_engine_runs = waves.num_engine_runs;
  ordered.nodes.resize(count);
  for (size_t old = 0; old < count; ++old) {
    SubgraphNode node = std::move(waves.nodes[old]);
    if (node.parent >= 0) node.parent = new_index[static_cast<size_t>(node.parent)];
    for (int& child : node.children) child = new_index[static_cast<size_t>(child)];
    ordered.nodes[static_cast<size_t>(new_index[old])] = std::move(node);
  }
  for (const int old : leaf_order) {
    const int index = new_index[static_cast<size_t>(old)];
    SubgraphNode& node = ordered.nodes[static_cast<size_t>(index)];
    AcceptedSubgraph accepted = std::move(waves.accepted[static_cast<size_t>(node.accepted_index)]);
    accepted.node = index;
    node.accepted_index = static_cast<int>(ordered.accepted.size());
    ordered.accepted.push_back(std::move(accepted));
  }
  return ordered;
}

}  // namespace

const char* SubgraphStatusName(SubgraphStatus status) {
  switch (status) {
    case SubgraphStatus::kSplit: return "split";
    case SubgraphStatus::kConsistent: return "consistent";
    case SubgraphStatus::kTiny: return "tiny";
    case SubgraphStatus::kUnsplittable: return "unsplittable";
    case SubgraphStatus::kMaxDepth: return "max_depth";
    case SubgraphStatus::kSinglePass: return "single_pass";
  }
  return "unknown";
}

SubgraphSolution SolutionFromModel(const std::vector<IndexT>& view_ids, const SfmData& model) {
  SubgraphSolution solution;
  solution.view_ids.insert(view_ids.begin(), view_ids.end());
  for (IndexT view_id : view_ids) {
    const auto it = model.views.find(view_id);
    if (it == model.views.end() || !model.IsPosed(it->second)) continue;
    solution.poses.emplace(view_id, model.PoseOf(it->second));
  }
  solution.landmarks = model.structure;
  return solution;
}

RecursivePartitionResult PartitionViewGraph(const RecursivePartitionOptions& options, const ViewGraph& graph,
                                            const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                            const CaptureOrder& capture_order, const ProgressCallback& progress) {
  return Renumber(Partitioner(options, graph, views_and_intrinsics, features, capture_order, progress).Run());
}

std::vector<EdgeOfSubgraphs> EdgesOfAcceptedSubgraphs(const ViewGraph& graph,
                                                      const std::vector<AcceptedSubgraph>& accepted) {
  std::map<IndexT, int> subgraph_of;
  for (size_t k = 0; k < accepted.size(); ++k) {
    for (IndexT view : accepted[k].solution.view_ids) subgraph_of[view] = static_cast<int>(k);
  }
  std::vector<EdgeOfSubgraphs> edges;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    const auto a = subgraph_of.find(pair.first);
    const auto b = subgraph_of.find(pair.second);
    if (a != subgraph_of.end() && b != subgraph_of.end()) edges.push_back({pair, a->second, b->second});
  });
  return edges;
}

void RecursivePartitionOptions::Check() const {
  louvain.Check();
  RequireAtLeast(num_threads, 1, "RecursivePartitionOptions::num_threads");
  RequireInRange(max_depth, 0, 64, "RecursivePartitionOptions::max_depth");
  consistency.Check();
  engine.Check();  // before any community is solved, not at the first one
}

}  // namespace sfm_pruning
