// Bundle adjustment of the cameras on a well-distributed subset of the landmarks, for the first
// adjustment after positioning: its start is far from the optimum (tens of pixels), so it takes
// many iterations, and each iteration costs in proportion to the observations. The cameras are
// as well determined by a few hundred landmarks per view spread over the image
// (track_subsampling.hpp); the other landmarks are then re-triangulated from the adjusted cameras
// (retriangulation.hpp), and the next, full adjustment starts close to its optimum.
#pragma once

#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/global/retriangulation.hpp"
#include "sfm_pruning/global/track_subsampling.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// Adjusts poses, intrinsics (as `bundle` asks) and the selected landmarks, then retriangulates
// every landmark with `retriangulation` (no track completion: nothing was removed). The result is
// the subset's bundle adjustment (its counts are the subset's). Without a cap, or when the cap
// selects every landmark, it is AdjustBundle. On failure sfm_data is untouched.
BundleAdjustmentResult AdjustBundleOnSubset(const BundleAdjustmentOptions& bundle,
                                            const TrackSubsamplingOptions& subsampling,
                                            const RetriangulationOptions& retriangulation, SfmData* sfm_data);

}  // namespace sfm_pruning
