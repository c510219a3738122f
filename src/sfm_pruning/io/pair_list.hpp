// OpenMVG pair lists (FORMATS.md §2.6), e.g. the pairs.bin of main_PairGenerator, which is text
// despite its extension. Each line "I J K ..." lists the pairs (I, J), (I, K), ...; view ids are
// assumed to be 0 ... N-1, as OpenMVG's matcher assumes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

// Ordered set of pairs, each stored as (min, max).
using PairSet = std::set<ViewPair>;

// Throws Error naming the file and line for a line with a single token, a non-numeric token,
// I == J, or an index >= `num_views`. Blank lines are skipped.
PairSet ReadPairList(const std::filesystem::path& path, size_t num_views);

// One "I J" line per pair, in set order. Atomic.
void WritePairList(const std::filesystem::path& path, const PairSet& pairs);

}  // namespace sfm_pruning
