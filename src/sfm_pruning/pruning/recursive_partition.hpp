// Recursive subgraph partition (paper, "Subgraph Partition"; METHOD.md §3): the view graph is
// split by Louvain into communities; each community is reconstructed on its own by the GLOBAL
// engine (RunGlobalEngine on the induced subgraph) and its solution is tested for consistency
// (consistency_tests.hpp). A community that fails is partitioned again.
//
// Termination (the paper does not spell it out). A community is accepted as is when
//   - it passes the consistency tests (kConsistent);
//   - it has at most tiny_subgraph_size views (kTiny): 1 view gets the identity pose and no
//     points; 2 views are reconstructed by the engine (min track length 2), and when the engine
//     fails they get the edge's relative pose (first view at the identity) and no points;
//   - Louvain returns it as a single community (kUnsplittable), unless bisect_unsplittable cuts it;
//   - it sits at max_depth (kMaxDepth) or recursion is off (kSinglePass).
// The root (depth 0) is the whole input graph; it is always split first, never solved unless
// Louvain cannot split it. Every node of the tree is kept for the report.
//
// Parallel and deterministic: the communities of one level are solved and tested in parallel
// (num_threads), each by a single-threaded engine run, so the partition does not depend on the
// thread count; the tree and the accepted subgraphs come out in depth-first order (communities in
// Louvain's canonical order, largest first). Louvain and the engine are seeded from the options.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/pruning/consistency_tests.hpp"
#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"
#include "sfm_pruning/view_graph/louvain.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct RecursivePartitionOptions {
  bool recursive = true;  // false: a single Louvain pass, every community accepted (ablation)
  LouvainOptions louvain;
  // The edge similarity Louvain maximises modularity on. kInliers is the paper's |M_ij|;
  // kDistinctiveMatches weighs each inlier by how few views its features match in
  // (view_graph/distinctive_weights.hpp), so repeated structure that every view sees counts little.
  // Only Louvain sees it: the per-community engine runs keep the inlier weights.
  enum class EdgeWeight { kInliers, kDistinctiveMatches };
  EdgeWeight edge_weight = EdgeWeight::kDistinctiveMatches;
  ConsistencyTestOptions consistency;  // each test can be switched off there
  GlobalEngineOptions engine;          // per-community reconstruction (engine.num_threads: 1, see above)
  int num_threads = 1;                 // communities solved at the same time
  size_t tiny_subgraph_size = 2;       // communities of at most this many views are accepted
  int max_depth = 8;                   // nodes at this depth are not split again
  // An inconsistent community that Louvain returns whole is cut in two by spectral bisection
  // (view_graph/spectral_bisection.hpp) instead of being accepted with its wrong edge, when it has
  // at least four views (a half of one view would have no landmarks to place its neighbours with).
  // Not in the paper; false = METHOD.md's termination. On the synthetic street
  // the thin run's {10-13} holds the twin-dominated edge 10-13, fails the translation test and was
  // accepted as unsplittable; bisected, the inter-subgraph pruning judges that edge
  // (docs/pruning.md).
  bool bisect_unsplittable = true;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

enum class SubgraphStatus {
  kSplit,         // inner node: partitioned into its children
  kConsistent,    // accepted: passed the consistency tests
  kTiny,          // accepted: at most tiny_subgraph_size views
  kUnsplittable,  // accepted: Louvain returned a single community
  kMaxDepth,      // accepted: inconsistent, but at max_depth
  kSinglePass,    // accepted: recursion off
};

// "split", "consistent", "tiny", "unsplittable", "max_depth", "single_pass".
const char* SubgraphStatusName(SubgraphStatus status);

struct SubgraphNode {
  int parent = -1;  // index in RecursivePartitionResult::nodes; -1 for the root
  int depth = 0;
  std::vector<IndexT> view_ids;  // sorted
  std::vector<int> children;
  SubgraphStatus status = SubgraphStatus::kSplit;
  bool solved = false;          // the engine ran on it (or it got the tiny fallback)
  bool engine_success = false;  // RunGlobalEngine succeeded
  std::string engine_message;
  size_t num_edges = 0;         // valid edges of the induced subgraph
  size_t num_registered = 0;
  size_t num_landmarks = 0;
  bool consistency_tested = false;
  ConsistencyReport consistency;  // violations + error summaries (empty when not tested)
  double seconds = 0.0;           // engine + tests of this node
  int accepted_index = -1;        // index in `accepted` when accepted
  bool bisected = false;          // split by spectral bisection (bisect_unsplittable), not Louvain
};

struct AcceptedSubgraph {
  int node = -1;  // index in RecursivePartitionResult::nodes
  SubgraphSolution solution;
};

// A valid edge of a graph whose two views lie in accepted subgraphs, with the subgraphs' indices.
struct EdgeOfSubgraphs {
  ViewPair pair;
  int k_first = -1;   // subgraph of pair.first
  int k_second = -1;  // subgraph of pair.second
};

// Every valid edge of `graph` between views of accepted subgraphs (inside one or between two), in
// ViewPair order.
std::vector<EdgeOfSubgraphs> EdgesOfAcceptedSubgraphs(const ViewGraph& graph,
                                                      const std::vector<AcceptedSubgraph>& accepted);

struct RecursivePartitionResult {
  std::vector<SubgraphNode> nodes;  // nodes[0] = root; a node's children are consecutive, depth first
  std::vector<AcceptedSubgraph> accepted;  // in acceptance order (depth first, largest first)
  size_t num_engine_runs = 0;
};

// The solution of a RunGlobalEngine output: poses re-keyed by view id, every landmark.
SubgraphSolution SolutionFromModel(const std::vector<IndexT>& view_ids, const SfmData& model);

// Partitions the valid part of `graph` (every node of it; the caller restricts it to one
// component). Louvain weighs the edges between capture neighbours up when `capture_order` is used
// (capture_order.hpp). Progress: "subgraph partition" (nodes processed, nodes known so far).
RecursivePartitionResult PartitionViewGraph(const RecursivePartitionOptions& options, const ViewGraph& graph,
                                            const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                            const CaptureOrder& capture_order = CaptureOrder(),
                                            const ProgressCallback& progress = {});

}  // namespace sfm_pruning
