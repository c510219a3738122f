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
  kBruteForce,  // exact: all distances through one matrix product (BLAS) per pair
};

// kAuto takes brute force when n_a * n_b <= kAutoBruteForceBalance * (n_a + n_b): its cost grows
// with the product of the feature counts, FLANN's with their sum. Measured on fountain-P11 (2
// cores, OpenBLAS's sgemm, docs/frontend.md): brute force matches 8192 features per image in 75 %
// of FLANN's time at 64 checks and 12288 in 125 %, so the balance sits at about 10000 features per
// image. With a slow BLAS (the reference one) brute force is several times slower.
inline constexpr double kAutoBruteForceBalance = 5000.0;

struct DescriptorMatchingOptions {
  DescriptorMatcher matcher = DescriptorMatcher::kAuto;
  double max_ratio = 0.8;    // nearest / second nearest distance (not squared), COLMAP's default
  bool mutual_check = true;
  int flann_trees = 4;
  int flann_checks = 64;
  int min_num_matches = 15;  // pairs with fewer matches are left out (COLMAP's default)
  uint64_t seed = 0;         // the kd-trees' random split choices
  int num_threads = 1;       // pairs matched in parallel; the result does not depend on it

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Matches every pair of `pairs` whose views have descriptors (others are skipped). Progress
// stages: "indexing descriptors" (FLANN), "matching pairs".
PairwiseMatches MatchDescriptors(const FeaturesPerView& features, const PairSet& pairs,
                                 const DescriptorMatchingOptions& options, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
