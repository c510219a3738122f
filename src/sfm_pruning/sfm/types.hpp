// Basic id types shared by the whole library (OpenMVG-compatible).
#pragma once

#include <cstdint>
#include <limits>
#include <utility>

namespace sfm_pruning {

// Ids of views, intrinsics, poses, landmarks and features. 32-bit unsigned, as in OpenMVG.
using IndexT = uint32_t;
// "No id": written literally (4294967295) in sfm_data.json, e.g. for a view whose intrinsic is
// unknown.
inline constexpr IndexT kUndefinedIndex = std::numeric_limits<IndexT>::max();

// An unordered pair of view ids, always stored with first < second.
using ViewPair = std::pair<IndexT, IndexT>;
inline ViewPair MakeViewPair(IndexT a, IndexT b) { return a < b ? ViewPair{a, b} : ViewPair{b, a}; }

}  // namespace sfm_pruning
