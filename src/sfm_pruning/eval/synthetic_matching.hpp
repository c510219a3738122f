// Putative matching of synthetic features, done the way a real matcher does it (from the
// descriptors alone), then judged against the ground truth, then topped up with random wrong
// matches to reach the requested outlier ratio.
#pragma once

#include <map>
#include <random>
#include <vector>

#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"

namespace sfm_pruning {

// Brute-force nearest neighbours of a's descriptors among b's (squared L2). A match i -> j is
// kept when d1 < ratio^2 * d2 (Lowe's ratio on distances, first vs second neighbour) and, with
// `mutual`, i is also j's nearest neighbour in a. Sorted by i. Ties go to the lower index.
std::vector<FeatureMatch> MatchDescriptorsBruteForce(const FeatureSet& a, const FeatureSet& b, double ratio,
                                                     bool mutual);

// The ground truth a pair's matcher needs: landmark of every feature and appearance of every
// landmark.
struct MatchTruth {
  const std::vector<IndexT>* landmarks_a = nullptr;  // per feature of the first view
  const std::vector<IndexT>* landmarks_b = nullptr;
  const std::map<IndexT, IndexT>* landmark_appearance = nullptr;
};

// Counts true, twin and random matches (num_injected stays 0).
PairMatchStats ClassifyMatches(const std::vector<FeatureMatch>& matches, const MatchTruth& truth);

// Adds random one-to-one wrong matches between features not yet matched, so that random wrong
// matches make up `outlier_ratio` of the pair's matches (see SyntheticSceneOptions). Candidates
// that would be true or twin matches are skipped. Returns the number added; the result stays
// sorted by i.
size_t InjectRandomWrongMatches(const PairMatchStats& stats, double outlier_ratio, size_t num_features_a,
                                size_t num_features_b, const MatchTruth& truth, std::mt19937_64& rng,
                                std::vector<FeatureMatch>* matches);

}  // namespace sfm_pruning
