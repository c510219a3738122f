// The samples one RANSAC run of the inter-subgraph pruning draws from its pool of voting edges
// (subgraph_alignment.hpp).
//
// The paper draws num_iterations random samples. With the minimal sample of 2 edges and t true
// edges among n, a round is clean with chance C(t,2)/C(n,2): on the real street 4 true edges of 17
// between two subgraphs give 4.4 % per round, so one seed in four never draws a clean sample in
// 30 rounds and the pair takes the doppelgangers' transform (seed 7: AUC@5 65.8 instead of 97).
// When the pool has few distinct samples, trying each of them once costs about as much and
// makes the search complete: the pair's decision then no longer depends on the seed
// (docs/pruning.md, "Every sample when there are few").
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace sfm_pruning {

// C(n, k) as a double (inexact above 2^53, which no enumeration bound reaches).
double NumSubsets(size_t n, size_t k);

class RansacSamples {
 public:
  // Samples of `sample_size` positions in a pool of `pool_size` (sample_size ≤ pool_size): every
  // subset once, in lexicographic order, when there are at most `max_enumerated` of them
  // (0: never), otherwise `num_iterations` uniform draws from `rng`.
  RansacSamples(size_t pool_size, size_t sample_size, int num_iterations, size_t max_enumerated,
                std::mt19937_64* rng);

  bool enumerated() const { return enumerated_; }
  int size() const { return num_samples_; }  // samples this run draws

  // The next sample: sorted positions in [0, pool_size). Call size() times.
  std::vector<size_t> Next();

 private:
  size_t pool_size_;
  size_t sample_size_;
  bool enumerated_ = false;
  int num_samples_ = 0;
  std::mt19937_64* rng_;
  std::vector<size_t> subset_;  // enumeration: the next subset, ascending
  std::vector<size_t> order_;   // draws: scratch permutation
};

}  // namespace sfm_pruning
