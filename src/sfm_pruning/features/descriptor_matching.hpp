// Putative feature matches of image pairs by descriptor similarity: nearest neighbours by L2
// distance (FLANN randomized kd-trees, or exact brute force), Lowe's ratio test, and a mutual
// check (a match i -> j is kept only when j -> i is the best match back too).
#pragma once

#include <cstdint>

#include "sfm_pruning/io/pair_list.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

enum class DescriptorMatcher {
  kAuto,        // per pair, whichever of the two is cheaper for its feature counts (see below)
  kFlann,       // approximate: 4 randomized kd-trees per image, `flann_checks` leaves per query
  kBruteForce,  // exact: all distances through one matrix product per pair
};

// kAuto takes brute force when n_a * n_b <= kAutoBruteForceBalance * (n_a + n_b): its cost grows
// with the product of the feature counts, FLANN's with their sum. Measured on this project's
// build (2 cores, no -march): about 11 ns per descriptor pair against 20 us per FLANN query at 64
// checks, so brute force is cheaper up to about 3700 features per image (the temple ring's 1400),
// FLANN beyond (fountain-P11's 8192).
inline constexpr double kAutoBruteForceBalance = 1800.0;

struct DescriptorMatchingOptions {
  DescriptorMatcher matcher = DescriptorMatcher::kAuto;
  double max_ratio = 0.8;    // nearest / second nearest distance (not squared), COLMAP's default
  bool mutual_check = true;
  int flann_trees = 4;
  int flann_checks = 64;
  int min_num_matches = 15;  // pairs with fewer matches are left out (COLMAP's default)
  uint64_t seed = 0;         // the kd-trees' random split choices
  int num_threads = 1;       // pairs matched in parallel; the result does not depend on it
};

// Matches every pair of `pairs` whose views have descriptors (others are skipped). Progress
// stages: "indexing descriptors" (FLANN), "matching pairs".
PairwiseMatches MatchDescriptors(const FeaturesPerView& features, const PairSet& pairs,
                                 const DescriptorMatchingOptions& options, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
