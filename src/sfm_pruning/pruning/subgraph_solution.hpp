// SubgraphSolution: what the global estimation of one subgraph G_k leaves for the pruning
// (METHOD.md §3): its views, their absolute poses P̂_i^k and its point cloud X^k, all in the
// subgraph's own frame (arbitrary rotation, translation and scale), plus the helpers the
// inter-subgraph alignment needs: the subgraph's mean pose P_c^k and a landmark lookup by
// observation.
#pragma once

#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/sfm/landmark.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

struct SubgraphSolution {
  std::set<IndexT> view_ids;             // every view of the subgraph, posed or not
  std::map<IndexT, Pose> poses;          // by view id (not pose id), subgraph frame
  std::map<IndexT, Landmark> landmarks;  // X in the subgraph frame; observations by view id
};

// The arithmetic mean of the centres of the posed views (the origin when nothing is posed).
Eigen::Vector3d SubgraphMeanCentre(const SubgraphSolution& solution);

// The mean pose c of a subgraph: rotation = L2 geodesic (Karcher) mean of the world-to-camera
// rotations of its posed views (so3.hpp; the mean of the inverses is the inverse of the mean, so
// the direction convention does not matter), centre = arithmetic mean of their centres.
// Identity pose at the origin when nothing is posed.
Pose SubgraphMeanPose(const SubgraphSolution& solution);

// (view id, feature id) -> landmark id, over every observation of the solution's landmarks.
// A feature observed by two landmarks (should not happen) keeps the smaller landmark id.
using ObservationKey = std::pair<IndexT, IndexT>;  // (view id, feature id)
std::map<ObservationKey, IndexT> IndexLandmarksByObservation(const SubgraphSolution& solution);

}  // namespace sfm_pruning
