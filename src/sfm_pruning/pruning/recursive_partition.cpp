#include "sfm_pruning/pruning/recursive_partition.hpp"

#include <chrono>
#include <set>
#include <utility>

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class Partitioner {
 public:
  Partitioner(const RecursivePartitionOptions& options, const ViewGraph& graph, const SfmData& views_and_intrinsics,
              const FeaturesPerView& features, const ProgressCallback& progress)
      : options_(options),
        graph_(graph),
        views_and_intrinsics_(views_and_intrinsics),
        features_(features),
        progress_(progress) {}

  RecursivePartitionResult Run() {
    SubgraphNode root;
    root.view_ids.assign(graph_.Nodes().begin(), graph_.Nodes().end());
    root.num_edges = graph_.NumValidEdges();
    result_.nodes.push_back(std::move(root));
    if (result_.nodes[0].view_ids.empty()) return std::move(result_);
    if (!Split(0)) {
      // Louvain cannot split the whole graph: it is one subgraph, reconstructed as is.
      ViewGraph induced = graph_;
      SubgraphSolution solution = Solve(0, induced);
      Test(0, induced, solution);
      Accept(0, SubgraphStatus::kUnsplittable, std::move(solution));
    }
    ReportProgress(progress_, "subgraph partition", result_.nodes.size(), result_.nodes.size());
    return std::move(result_);
  }

 private:
  // Louvain on the node's induced subgraph; adds the children and processes them (depth first).
  // False when Louvain returns fewer than two communities.
  bool Split(int index) {
    const std::vector<IndexT>& views = result_.nodes[static_cast<size_t>(index)].view_ids;
    const ViewGraph induced = graph_.InducedSubgraph(std::set<IndexT>(views.begin(), views.end()));
    const LouvainResult louvain = DetectCommunitiesLouvain(induced, options_.louvain);
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
    for (int child : children) Process(child);
    return true;
  }

  void Process(int index) {
    ReportProgress(progress_, "subgraph partition", static_cast<size_t>(index), result_.nodes.size());
    const SubgraphNode& node = result_.nodes[static_cast<size_t>(index)];
    const ViewGraph induced = graph_.InducedSubgraph(std::set<IndexT>(node.view_ids.begin(), node.view_ids.end()));
    result_.nodes[static_cast<size_t>(index)].num_edges = induced.NumValidEdges();
    SubgraphSolution solution = Solve(index, induced);
    if (result_.nodes[static_cast<size_t>(index)].view_ids.size() <= options_.tiny_subgraph_size) {
      Accept(index, SubgraphStatus::kTiny, std::move(solution));
      return;
    }
    Test(index, induced, solution);
    const SubgraphNode& tested = result_.nodes[static_cast<size_t>(index)];
    if (tested.consistency.consistent) {
      Accept(index, SubgraphStatus::kConsistent, std::move(solution));
    } else if (!options_.recursive) {
      Accept(index, SubgraphStatus::kSinglePass, std::move(solution));
    } else if (tested.depth >= options_.max_depth) {
      Accept(index, SubgraphStatus::kMaxDepth, std::move(solution));
    } else if (!Split(index)) {
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
      ++result_.num_engine_runs;
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
  RecursivePartitionResult result_;
};

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
                                            const ProgressCallback& progress) {
  return Partitioner(options, graph, views_and_intrinsics, features, progress).Run();
}

}  // namespace sfm_pruning
