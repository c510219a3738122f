#include <gtest/gtest.h>

#include "graph_builders.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/view_graph/louvain.hpp"
#include "sfm_pruning/view_graph/spectral_bisection.hpp"

namespace sfm_pruning {
namespace {

using testing::AddClique;
using testing::AddWeightedEdges;

TEST(SpectralBisection, CutsTwoCliquesAtTheirBridge) {
  ViewGraph graph;
  AddClique(&graph, {0, 1, 2, 3}, 10.0);
  AddClique(&graph, {4, 5, 6, 7}, 10.0);
  AddWeightedEdges(&graph, {{3, 4, 1.0}});
  const auto [first, second] = SpectralBisection(graph);
  EXPECT_EQ(first, (NodeGroup{0, 1, 2, 3}));
  EXPECT_EQ(second, (NodeGroup{4, 5, 6, 7}));
}

// Four views that Louvain keeps together (the street's {10-13}: one weak view tied to three strong
// ones): the cut goes through the weakest edges and leaves two views on each side.
TEST(SpectralBisection, SplitsWhatLouvainKeepsWholeAtItsWeakestLinks) {
  ViewGraph graph;
  AddWeightedEdges(&graph, {{10, 11, 4.0}, {10, 12, 2.0}, {10, 13, 1.0}, {11, 12, 6.0}, {11, 13, 5.0}, {12, 13, 9.0}});
  ASSERT_EQ(DetectCommunitiesLouvain(graph, {}).communities.size(), 1u);
  const auto [first, second] = SpectralBisection(graph);
  EXPECT_EQ(first, (NodeGroup{10, 11}));
  EXPECT_EQ(second, (NodeGroup{12, 13}));
}

TEST(SpectralBisection, PathsAndOddSizesAreHalvedInOrder) {
  ViewGraph path;
  AddWeightedEdges(&path, {{0, 1, 1.0}, {1, 2, 1.0}, {2, 3, 1.0}, {3, 4, 1.0}});
  const auto [first, second] = SpectralBisection(path);
  EXPECT_EQ(first.size() + second.size(), 5u);
  EXPECT_TRUE((first == NodeGroup{0, 1} && second == NodeGroup{2, 3, 4}) ||
              (first == NodeGroup{0, 1, 2} && second == NodeGroup{3, 4}))
      << first.size() << " | " << second.size();
  // Deterministic.
  EXPECT_EQ(SpectralBisection(path), SpectralBisection(path));
}

TEST(SpectralBisection, NeedsTwoViews) {
  ViewGraph single;
  single.AddNode(3);
  EXPECT_THROW(SpectralBisection(single), Error);
}

}  // namespace
}  // namespace sfm_pruning
