#include "sfm_pruning/view_graph/louvain.hpp"

#include <igraph/igraph.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/view_graph/dense_node_index.hpp"

namespace sfm_pruning {
namespace {

// igraph's RNG and error handlers are process-wide; this mutex serialises every use of them.
std::mutex& IgraphMutex() {
  static std::mutex mutex;
  return mutex;
}

// While alive, igraph errors return codes instead of aborting the process, and nothing is
// printed (library code never prints): we turn the codes into exceptions ourselves.
class QuietIgraphHandlers {
 public:
  QuietIgraphHandlers()
      : previous_error_(igraph_set_error_handler(igraph_error_handler_ignore)),
        previous_warning_(igraph_set_warning_handler(igraph_warning_handler_ignore)) {}
  ~QuietIgraphHandlers() {
    igraph_set_error_handler(previous_error_);
    igraph_set_warning_handler(previous_warning_);
  }
  QuietIgraphHandlers(const QuietIgraphHandlers&) = delete;
  QuietIgraphHandlers& operator=(const QuietIgraphHandlers&) = delete;

 private:
  igraph_error_handler_t* previous_error_;
  igraph_warning_handler_t* previous_warning_;
};

void CheckIgraph(igraph_error_t code, const char* call) {
  if (code != IGRAPH_SUCCESS) {
    throw std::runtime_error(std::string("Louvain: ") + call + " failed: " + igraph_strerror(code));
  }
}

// Owns an initialised igraph object and destroys it on scope exit (igraph is a C API).
template <typename T, void (*Destroy)(T*)>
class IgraphOwned {
 public:
  IgraphOwned() = default;
  ~IgraphOwned() {
    if (initialized_) Destroy(&value_);
  }
  IgraphOwned(const IgraphOwned&) = delete;
  IgraphOwned& operator=(const IgraphOwned&) = delete;
  // Call once the igraph init function succeeded.
  void MarkInitialized() { initialized_ = true; }
  T* get() { return &value_; }

 private:
  T value_{};
  bool initialized_ = false;
};

using OwnedGraph = IgraphOwned<igraph_t, igraph_destroy>;
using OwnedRealVector = IgraphOwned<igraph_vector_t, igraph_vector_destroy>;
using OwnedIntVector = IgraphOwned<igraph_vector_int_t, igraph_vector_int_destroy>;
using OwnedIntMatrix = IgraphOwned<igraph_matrix_int_t, igraph_matrix_int_destroy>;

// The valid edges with their weights, checked: igraph would reject negative weights with a
// less helpful message, and NaN would corrupt the modularity silently.
std::vector<std::pair<ViewPair, double>> WeightedValidEdges(const ViewGraph& graph) {
  std::vector<std::pair<ViewPair, double>> edges;
  graph.ForEachValidEdge([&edges](const ViewPair& pair, const ViewGraphEdge& edge) {
    if (!std::isfinite(edge.weight) || edge.weight < 0.0) {
      throw std::invalid_argument("Louvain: edge (" + std::to_string(pair.first) + ", " +
                                  std::to_string(pair.second) + ") has weight " +
                                  std::to_string(edge.weight) + "; weights must be finite and >= 0");
    }
    edges.emplace_back(pair, edge.weight);
  });
  return edges;
}

LouvainResult OneCommunityPerNode(const ViewGraph& graph) {
  LouvainResult result;
  for (IndexT id : graph.Nodes()) result.communities.push_back({id});
  return result;
}

}  // namespace

LouvainResult DetectCommunitiesLouvain(const ViewGraph& graph, const LouvainOptions& options) {
  options.Check();
  const std::vector<std::pair<ViewPair, double>> edges = WeightedValidEdges(graph);
  double total_weight = 0.0;
  for (const auto& [pair, weight] : edges) total_weight += weight;
  // Modularity is 0/0 without edge weight; igraph would return NaN. Nothing attracts any node.
  if (total_weight == 0.0) return OneCommunityPerNode(graph);

  const DenseNodeIndex index(graph);
  const auto num_edges = static_cast<igraph_integer_t>(edges.size());

  std::lock_guard<std::mutex> lock(IgraphMutex());
  const QuietIgraphHandlers quiet;

  OwnedIntVector endpoints;
  CheckIgraph(igraph_vector_int_init(endpoints.get(), 2 * num_edges), "igraph_vector_int_init");
  endpoints.MarkInitialized();
  OwnedRealVector weights;
  CheckIgraph(igraph_vector_init(weights.get(), num_edges), "igraph_vector_init");
  weights.MarkInitialized();
  for (igraph_integer_t e = 0; e < num_edges; ++e) {
    const auto& [pair, weight] = edges[static_cast<size_t>(e)];
    VECTOR(*endpoints.get())[2 * e] = static_cast<igraph_integer_t>(index.IndexOf(pair.first));
    VECTOR(*endpoints.get())[2 * e + 1] = static_cast<igraph_integer_t>(index.IndexOf(pair.second));
    VECTOR(*weights.get())[e] = weight;
  }

  OwnedGraph igraph;
  CheckIgraph(igraph_create(igraph.get(), endpoints.get(), static_cast<igraph_integer_t>(index.size()),
                            IGRAPH_UNDIRECTED),
              "igraph_create");
  igraph.MarkInitialized();

  OwnedIntVector membership;
  CheckIgraph(igraph_vector_int_init(membership.get(), 0), "igraph_vector_int_init");
  membership.MarkInitialized();
  OwnedIntMatrix levels;
  CheckIgraph(igraph_matrix_int_init(levels.get(), 0, 0), "igraph_matrix_int_init");
  levels.MarkInitialized();
  OwnedRealVector level_modularity;
  CheckIgraph(igraph_vector_init(level_modularity.get(), 0), "igraph_vector_init");
  level_modularity.MarkInitialized();

  // Re-seeded on every call: the RNG state left by an earlier call must not leak in.
  CheckIgraph(igraph_rng_seed(igraph_rng_default(), static_cast<igraph_uint_t>(options.seed)),
              "igraph_rng_seed");
  CheckIgraph(igraph_community_multilevel(igraph.get(), weights.get(), options.resolution, membership.get(),
                                          levels.get(), level_modularity.get()),
              "igraph_community_multilevel");

  LouvainResult result;
  // igraph returns in `membership` the level of highest modularity.
  result.num_levels = static_cast<int>(igraph_matrix_int_nrow(levels.get()));
  result.modularity =
      igraph_vector_size(level_modularity.get()) > 0 ? igraph_vector_max(level_modularity.get()) : 0.0;
  std::map<igraph_integer_t, NodeGroup> by_label;
  for (size_t k = 0; k < index.size(); ++k) {
    by_label[VECTOR(*membership.get())[static_cast<igraph_integer_t>(k)]].push_back(index.IdOf(k));
  }
  for (auto& [label, members] : by_label) result.communities.push_back(std::move(members));
  SortNodeGroups(&result.communities);
  return result;
}

void LouvainOptions::Check() const {
  // igraph rejects a negative gamma and 0 ignores the degrees (one community per component); the
  // upper bound is generous (far beyond it every node is a community of its own).
  RequirePositiveAtMost(resolution, 1e6, "LouvainOptions::resolution");
}

}  // namespace sfm_pruning
