#include "sfm_pruning/io/openmvg_sfm_data_format.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::openmvg_format {

PolymorphicEnvelope PolymorphicIdWriter::Next(const std::string& type_name) {
  PolymorphicEnvelope envelope;
  envelope.pointer_id = kNewIdFlag | ++pointer_count_;
  if (type_name.empty()) return envelope;
  const auto it = type_ids_.find(type_name);
  if (it != type_ids_.end()) {
    envelope.type_id = it->second;
  } else {
    const auto id = static_cast<uint32_t>(type_ids_.size() + 1);
    type_ids_.emplace(type_name, id);
    envelope.type_id = kNewIdFlag | id;
    envelope.new_type_name = type_name;
  }
  return envelope;
}

bool PolymorphicIdReader::Register(uint32_t id, const std::string& name) {
  if (!(id & kNewIdFlag)) return false;
  names_[id & ~kNewIdFlag] = name;
  return true;
}

const std::string* PolymorphicIdReader::Find(uint32_t id) const {
  const auto it = names_.find(id);
  return it == names_.end() ? nullptr : &it->second;
}

const char* DistortionFieldName(CameraModel model) {
  switch (model) {
    case CameraModel::kPinholeRadialK1:
      return "disto_k1";
    case CameraModel::kPinholeRadialK3:
      return "disto_k3";
    case CameraModel::kPinholeBrownT2:
      return "disto_t2";
    case CameraModel::kFisheye:
      return "fisheye";
    case CameraModel::kPinhole:
    case CameraModel::kPinholeFxFy:
    case CameraModel::kSpherical:
      break;
  }
  return nullptr;
}

IntrinsicRecord ToIntrinsicRecord(const CameraIntrinsics& intrinsic) {
  IntrinsicRecord record;
  record.width = intrinsic.width();
  record.height = intrinsic.height();
  const std::vector<double>& p = intrinsic.params();
  switch (intrinsic.model()) {
    case CameraModel::kSpherical:
      record.type_name = CameraModelName(CameraModel::kSpherical);
      return record;
    case CameraModel::kPinholeFxFy:
      // Written as an OpenMVG pinhole with focal fx; fy rides along in an extra field.
      record.type_name = CameraModelName(CameraModel::kPinhole);
      record.focal_length = p[0];
      record.focal_length_y = p[1];
      record.principal_point = {p[2], p[3]};
      return record;
    default:
      record.type_name = CameraModelName(intrinsic.model());
      record.focal_length = p[0];
      record.principal_point = {p[1], p[2]};
      record.distortion.assign(p.begin() + camera_models::kFirstDistortionParam, p.end());
      return record;
  }
}

bool ModelFromTypeName(const std::string& type_name, CameraModel* model) {
  return CameraModelFromName(type_name, model) && *model != CameraModel::kPinholeFxFy;
}

namespace {

// NaN focal lengths compare unequal; they still mean "no second focal".
bool SameFocal(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

CameraIntrinsics FromIntrinsicRecord(CameraModel model, const IntrinsicRecord& record,
                                     const std::string& where) {
  if (model == CameraModel::kSpherical) {
    return CameraIntrinsics(model, record.width, record.height, {});
  }
  if (record.principal_point.size() != 2) {
    throw FileError(where + ".principal_point",
                    "expected 2 numbers, got " + std::to_string(record.principal_point.size()));
  }
  const double cx = record.principal_point[0];
  const double cy = record.principal_point[1];
  if (model == CameraModel::kPinhole && record.focal_length_y &&
      !SameFocal(*record.focal_length_y, record.focal_length)) {
    return CameraIntrinsics(CameraModel::kPinholeFxFy, record.width, record.height,
                            {record.focal_length, *record.focal_length_y, cx, cy});
  }
  const size_t num_distortion = NumCameraParams(model) - camera_models::kFirstDistortionParam;
  if (record.distortion.size() != num_distortion) {
    const char* field = DistortionFieldName(model);
    throw FileError(where + "." + (field ? field : "distortion"),
                    "expected " + std::to_string(num_distortion) + " numbers, got " +
                        std::to_string(record.distortion.size()));
  }
  std::vector<double> params = {record.focal_length, cx, cy};
  params.insert(params.end(), record.distortion.begin(), record.distortion.end());
  return CameraIntrinsics(model, record.width, record.height, std::move(params));
}

}  // namespace sfm_pruning::openmvg_format
