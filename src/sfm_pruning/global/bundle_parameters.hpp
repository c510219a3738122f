// The parameter blocks of a bundle adjustment, copied out of an SfmData into one contiguous
// buffer in id order: landmarks, then poses (quaternion w, x, y, z + centre), then intrinsics.
//
// Why a copy: Ceres keeps the blocks of an elimination group in a std::set<double*>, i.e. in
// address order. Blocks living in std::map nodes have run-dependent addresses, which changed the
// elimination order and the result in the last bits from one run to the next. In one buffer the
// address order is the id order, so the same input gives bitwise the same output.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "sfm_pruning/global/bundle_observations.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

class BundleParameters {
 public:
  // A landmark takes part when it has at least two posed observations; its posed views bring
  // their pose and intrinsics in.
  explicit BundleParameters(const SfmData& data);

  const std::vector<IndexT>& landmark_ids() const { return landmark_ids_; }
  // Posed observations of landmark_ids()[k].
  const std::vector<PosedObservation>& observations(size_t k) const { return observations_[k]; }
  size_t num_poses() const { return pose_slots_.size(); }
  size_t num_intrinsics() const { return intrinsic_offsets_.size(); }
  const std::map<IndexT, size_t>& pose_slots() const { return pose_slots_; }
  const std::map<IndexT, size_t>& intrinsic_offsets() const { return intrinsic_offsets_; }

  double* point(size_t k) { return &values_[3 * k]; }
  // The pose block: quaternion (w, x, y, z), then centre.
  double* pose(IndexT pose_id) { return &values_[PoseOffset(pose_id)]; }
  const double* center(IndexT pose_id) const { return &values_[PoseOffset(pose_id) + 4]; }
  double* intrinsics(IndexT intrinsic_id) { return &values_[intrinsic_offsets_.at(intrinsic_id)]; }

  // Copies the values back; the pose `keep_pose_id` (the gauge) is left exactly as it was,
  // since the quaternion round trip would change its last bits.
  void WriteBack(IndexT keep_pose_id, SfmData* data) const;

 private:
  size_t PoseOffset(IndexT pose_id) const { return poses_offset_ + 7 * pose_slots_.at(pose_id); }

  std::vector<IndexT> landmark_ids_;
  std::vector<std::vector<PosedObservation>> observations_;
  std::map<IndexT, size_t> pose_slots_;         // pose id -> index among poses
  std::map<IndexT, size_t> intrinsic_offsets_;  // intrinsic id -> offset in values_
  size_t poses_offset_ = 0;
  std::vector<double> values_;
};

}  // namespace sfm_pruning
