#include "sfm_pruning/view_graph/union_find.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {
namespace {

TEST(UnionFind, MergesAndCountsSets) {
  UnionFind<IndexT> sets(6);
  EXPECT_EQ(sets.NumSets(), 6u);
  EXPECT_TRUE(sets.Union(0, 1));
  EXPECT_TRUE(sets.Union(2, 3));
  EXPECT_TRUE(sets.Union(1, 3));
  EXPECT_FALSE(sets.Union(0, 2));  // already one set
  EXPECT_EQ(sets.NumSets(), 3u);
  EXPECT_EQ(sets.SetSize(3), 4u);
  EXPECT_EQ(sets.SetSize(4), 1u);
  EXPECT_TRUE(sets.Connected(0, 3));
  EXPECT_FALSE(sets.Connected(0, 4));
  EXPECT_EQ(sets.NumElements(), 6u);
}

TEST(UnionFind, RootIsIndependentOfArgumentOrder) {
  // Equal sizes: the smaller root survives; otherwise the larger set's root.
  UnionFind<size_t> sets(5);
  sets.Union(3, 1);
  EXPECT_EQ(sets.Find(3), 1u);
  sets.Union(4, 2);
  EXPECT_EQ(sets.Find(4), 2u);
  sets.Union(0, 4);  // {0} joins {2, 4}
  EXPECT_EQ(sets.Find(0), 2u);
  sets.Union(1, 0);  // {1, 3} (size 2) joins {0, 2, 4} (size 3)
  for (size_t k = 0; k < 5; ++k) EXPECT_EQ(sets.Find(k), 2u);
}

TEST(UnionFind, AgreesWithNaiveRelabelingOnRandomUnions) {
  constexpr size_t kNum = 300;
  std::mt19937 rng(5);
  std::uniform_int_distribution<size_t> pick(0, kNum - 1);
  UnionFind<size_t> sets(kNum);
  std::vector<size_t> label(kNum);
  for (size_t k = 0; k < kNum; ++k) label[k] = k;
  for (int step = 0; step < 200; ++step) {
    const size_t a = pick(rng);
    const size_t b = pick(rng);
    const bool merged = sets.Union(a, b);
    EXPECT_EQ(merged, label[a] != label[b]);
    const size_t from = label[b];
    for (size_t& l : label) {
      if (l == from) l = label[a];
    }
  }
  size_t distinct = 0;
  for (size_t x = 0; x < kNum; ++x) {
    if (std::count(label.begin(), label.begin() + x, label[x]) == 0) ++distinct;  // first of its set
    for (size_t y = 0; y < kNum; y += 7) EXPECT_EQ(sets.Connected(x, y), label[x] == label[y]);
    EXPECT_EQ(sets.SetSize(x), static_cast<size_t>(std::count(label.begin(), label.end(), label[x])));
  }
  EXPECT_EQ(sets.NumSets(), distinct);
}

}  // namespace
}  // namespace sfm_pruning
