// Triangulation of points from bearing vectors and known poses, triangulation angles and the
// reprojection-free cheirality test. Bearings are unit (or at least non-zero) vectors in the
// camera frame (CameraIntrinsics::Unproject); poses follow pose.hpp.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {

// Two-view midpoint triangulation in camera i's frame.
struct TwoViewPoint {
  Eigen::Vector3d point_i = Eigen::Vector3d::Zero();  // camera-i coordinates
  // Signed distances along each bearing (in units of the bearing's length) to the closest points
  // of the two rays; both positive means the point lies in front of both cameras.
  double depth_i = 0.0;
  double depth_j = 0.0;
};

// Midpoint of the common perpendicular of ray i and ray j (relative pose i -> j, so the centre of
// j is relative_ij.CenterOfJInI()). Empty when the rays are parallel to within
// `min_parallax_rad` (the point is at infinity or the baseline is zero).
std::optional<TwoViewPoint> TriangulateTwoView(const RelativePose& relative_ij,
                                               const Eigen::Vector3d& bearing_i,
                                               const Eigen::Vector3d& bearing_j,
                                               double min_parallax_rad = 1e-9);

enum class TriangulationMethod {
  // Linear DLT: two equations per view from the plane orthogonal to the bearing, homogeneous
  // solution by SVD. Minimises an algebraic error; the usual choice.
  kDlt,
  // Point closest to all rays in the least-squares sense (multi-view midpoint); minimises the
  // sum of squared distances to the rays, so far views weigh more.
  kMidpoint,
};

// World point seen by every (pose, bearing) pair. Needs at least two views with non-parallel
// rays; empty otherwise (or when the DLT solution lies at infinity).
std::optional<Eigen::Vector3d> TriangulateMultiView(const std::vector<Pose>& poses,
                                                    const std::vector<Eigen::Vector3d>& bearings,
                                                    TriangulationMethod method = TriangulationMethod::kDlt);

// Angle in radians at `point` between the rays to the two camera centres.
double TriangulationAngle(const Eigen::Vector3d& center_a, const Eigen::Vector3d& center_b,
                          const Eigen::Vector3d& point);

// Largest pairwise triangulation angle of a track (radians); 0 for fewer than two centres.
// Quadratic in the track length.
double MaxTriangulationAngle(const std::vector<Eigen::Vector3d>& centers, const Eigen::Vector3d& point);

// Cheirality without projection: the point lies on the observed side of the camera, i.e. its
// camera-frame position has a positive component along the bearing. Works for any camera model,
// spherical included.
inline bool IsInFront(const Pose& pose, const Eigen::Vector3d& bearing, const Eigen::Vector3d& point_world) {
  return bearing.dot(pose.ToCamera(point_world)) > 0.0;
}

// IsInFront for every (pose, bearing) pair.
bool IsInFrontOfAll(const std::vector<Pose>& poses, const std::vector<Eigen::Vector3d>& bearings,
                    const Eigen::Vector3d& point_world);

}  // namespace sfm_pruning
