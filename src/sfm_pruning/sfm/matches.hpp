// Pairwise feature matches, keyed by view pair (first < second), as in OpenMVG's match files.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct FeatureMatch {
  IndexT i = 0;  // feature index in the first view of the pair
  IndexT j = 0;  // feature index in the second view
  bool operator==(const FeatureMatch& o) const { return i == o.i && j == o.j; }
};

using PairwiseMatches = std::map<ViewPair, std::vector<FeatureMatch>>;

}  // namespace sfm_pruning
