// Groups of view ids (components, communities): one canonical order shared by every algorithm
// that returns a partition, so results compare equal across runs and modules.
#pragma once

#include <vector>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

using NodeGroup = std::vector<IndexT>;

// Sorts the ids inside each group, then the groups by size (largest first), ties by smallest id.
void SortNodeGroups(std::vector<NodeGroup>* groups);

}  // namespace sfm_pruning
