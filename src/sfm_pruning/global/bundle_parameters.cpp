#include "sfm_pruning/global/bundle_parameters.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace sfm_pruning {

BundleParameters::BundleParameters(const SfmData& data) {
  for (const auto& [landmark_id, landmark] : data.structure) {
    std::vector<PosedObservation> posed = PosedObservationsOf(data, landmark);
    if (posed.size() < 2) continue;
    for (const PosedObservation& obs : posed) {
      pose_slots_.emplace(obs.view->id_pose, 0);
      intrinsic_offsets_.emplace(obs.view->id_intrinsic, 0);
    }
    landmark_ids_.push_back(landmark_id);
    observations_.push_back(std::move(posed));
  }
  size_t slot = 0;
  for (auto& [pose_id, pose_slot] : pose_slots_) pose_slot = slot++;
  poses_offset_ = 3 * landmark_ids_.size();
  size_t offset = poses_offset_ + 7 * pose_slots_.size();
  for (auto& [intrinsic_id, intrinsic_offset] : intrinsic_offsets_) {
    intrinsic_offset = offset;
    offset += data.intrinsics.at(intrinsic_id).params().size();
  }
  values_.resize(offset);

  for (size_t k = 0; k < landmark_ids_.size(); ++k) {
    Eigen::Map<Eigen::Vector3d>(point(k)) = data.structure.at(landmark_ids_[k]).X;
  }
  for (const auto& [pose_id, pose_slot] : pose_slots_) {
    const Pose& given = data.poses.at(pose_id);
    const Eigen::Quaterniond q = Eigen::Quaterniond(given.rotation).normalized();
    double* block = pose(pose_id);
    block[0] = q.w();
    block[1] = q.x();
    block[2] = q.y();
    block[3] = q.z();
    Eigen::Map<Eigen::Vector3d>(block + 4) = given.center;
  }
  for (const auto& [intrinsic_id, intrinsic_offset] : intrinsic_offsets_) {
    const std::vector<double>& params = data.intrinsics.at(intrinsic_id).params();
    std::copy(params.begin(), params.end(), values_.begin() + static_cast<std::ptrdiff_t>(intrinsic_offset));
  }
}

void BundleParameters::WriteBack(IndexT keep_pose_id, SfmData* data) const {
  for (size_t k = 0; k < landmark_ids_.size(); ++k) {
    data->structure.at(landmark_ids_[k]).X = Eigen::Map<const Eigen::Vector3d>(&values_[3 * k]);
  }
  for (const auto& [pose_id, pose_slot] : pose_slots_) {
    if (pose_id == keep_pose_id) continue;
    const double* q = &values_[PoseOffset(pose_id)];
    const Eigen::Quaterniond rotation(q[0], q[1], q[2], q[3]);
    data->poses[pose_id] = Pose(rotation.normalized().toRotationMatrix(), Eigen::Map<const Eigen::Vector3d>(q + 4));
  }
  for (const auto& [intrinsic_id, intrinsic_offset] : intrinsic_offsets_) {
    std::vector<double>& params = data->intrinsics.at(intrinsic_id).mutable_params();
    std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(intrinsic_offset), params.size(), params.begin());
  }
}

}  // namespace sfm_pruning
