// sfm_data.json writer. It drives cereal's own JSONOutputArchive with small mirror structs so that
// indentation, number formatting (rapidjson's shortest digits, "256.0", NaN / Infinity) and field
// order are byte for byte what OpenMVG writes. The polymorphic envelope is written by hand from
// PolymorphicIdWriter, which numbers types and pointers the way cereal's registry would; this
// keeps cereal's global polymorphic type registration out of the library.
#include <cereal/archives/json.hpp>
#include <cereal/types/string.hpp>
#include <cereal/types/vector.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "sfm_pruning/io/openmvg_sfm_data_format.hpp"

namespace sfm_pruning::openmvg_format {
namespace {

using Archive = cereal::JSONOutputArchive;
using cereal::make_nvp;

std::vector<double> ToStdVector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
std::vector<double> ToStdVector(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

// One element of a map written as an array: {"key": K, "value": V}.
template <typename Value>
struct KeyValue {
  IndexT key;
  Value value;
  void save(Archive& ar) const { ar(make_nvp("key", key), make_nvp("value", value)); }
};

template <typename Data>
struct PtrWrapper {
  uint32_t id;
  const Data& data;
  void save(Archive& ar) const { ar(make_nvp("id", id), make_nvp("data", data)); }
};

template <typename Data>
struct PolymorphicPointer {
  PolymorphicEnvelope envelope;
  Data data;
  void save(Archive& ar) const {
    ar(make_nvp("polymorphic_id", envelope.type_id));
    if (!envelope.new_type_name.empty()) ar(make_nvp("polymorphic_name", envelope.new_type_name));
    ar(make_nvp("ptr_wrapper", PtrWrapper<Data>{envelope.pointer_id, data}));
  }
};

struct ViewData {
  const View* view;
  void save(Archive& ar) const {
    ar(make_nvp("local_path", view->local_path), make_nvp("filename", view->filename),
       make_nvp("width", view->width), make_nvp("height", view->height), make_nvp("id_view", view->id_view),
       make_nvp("id_intrinsic", view->id_intrinsic), make_nvp("id_pose", view->id_pose));
    // view_priors: OpenMVG writes the prior fields only when the prior is enabled.
    if (view->center_prior) {
      ar(make_nvp("use_pose_center_prior", true),
         make_nvp("center_weight", ToStdVector(view->center_prior->weight)),
         make_nvp("center", ToStdVector(view->center_prior->center)));
    }
  }
};

// Spherical cameras store their base class through cereal::base_class, hence "value0".
struct ImageSize {
  uint32_t width;
  uint32_t height;
  void save(Archive& ar) const { ar(make_nvp("width", width), make_nvp("height", height)); }
};

struct IntrinsicData {
  CameraModel model;
  IntrinsicRecord record;
  void save(Archive& ar) const {
    if (!IsPinholeFamily(model)) {
      ar(make_nvp("value0", ImageSize{record.width, record.height}));
      return;
    }
    ar(make_nvp("width", record.width), make_nvp("height", record.height),
       make_nvp("focal_length", record.focal_length), make_nvp("principal_point", record.principal_point));
    if (const char* field = DistortionFieldName(model)) ar(make_nvp(field, record.distortion));
    if (record.focal_length_y) ar(make_nvp(kFocalLengthYField, *record.focal_length_y));
  }
};

struct PoseData {
  const Pose* pose;
  void save(Archive& ar) const {
    std::vector<std::vector<double>> rows;
    for (int r = 0; r < 3; ++r) rows.push_back(ToStdVector(Eigen::Vector3d(pose->rotation.row(r))));
    ar(make_nvp("rotation", rows), make_nvp("center", ToStdVector(pose->center)));
  }
};

struct ObservationData {
  const Observation* observation;
  void save(Archive& ar) const {
    ar(make_nvp("id_feat", observation->id_feat), make_nvp("x", ToStdVector(observation->x)));
  }
};

struct LandmarkData {
  const Landmark* landmark;
  void save(Archive& ar) const {
    std::vector<KeyValue<ObservationData>> observations;
    for (const auto& [view_id, observation] : landmark->observations) {
      observations.push_back({view_id, {&observation}});
    }
    ar(make_nvp("X", ToStdVector(landmark->X)), make_nvp("observations", observations));
  }
};

std::vector<KeyValue<LandmarkData>> LandmarkEntries(const std::map<IndexT, Landmark>& landmarks) {
  std::vector<KeyValue<LandmarkData>> entries;
  for (const auto& [id, landmark] : landmarks) entries.push_back({id, {&landmark}});
  return entries;
}

}  // namespace

void WriteSfmDataJson(const SfmData& data, SfmDataParts parts, std::ostream& out) {
  // Views come first: cereal numbers types and pointers in archive order.
  PolymorphicIdWriter ids;
  std::vector<KeyValue<PolymorphicPointer<ViewData>>> views;
  if (HasParts(parts, SfmDataParts::kViews)) {
    for (const auto& [id, view] : data.views) views.push_back({id, {ids.Next(ViewTypeName(view)), {&view}}});
  }
  std::vector<KeyValue<PolymorphicPointer<IntrinsicData>>> intrinsics;
  if (HasParts(parts, SfmDataParts::kIntrinsics)) {
    for (const auto& [id, intrinsic] : data.intrinsics) {
      IntrinsicRecord record = ToIntrinsicRecord(intrinsic);
      const PolymorphicEnvelope envelope = ids.Next(record.type_name);
      intrinsics.push_back({id, {envelope, {intrinsic.model(), std::move(record)}}});
    }
  }
  std::vector<KeyValue<PoseData>> extrinsics;
  if (HasParts(parts, SfmDataParts::kExtrinsics)) {
    for (const auto& [id, pose] : data.poses) extrinsics.push_back({id, {&pose}});
  }
  const std::map<IndexT, Landmark> none;
  const bool structure = HasParts(parts, SfmDataParts::kStructure);
  const bool control_points = HasParts(parts, SfmDataParts::kControlPoints);

  Archive ar(out);  // cereal's defaults: 4-space indent, as OpenMVG
  ar(make_nvp("sfm_data_version", std::string(kWrittenVersion)), make_nvp("root_path", data.root_path),
     make_nvp("views", views), make_nvp("intrinsics", intrinsics), make_nvp("extrinsics", extrinsics),
     make_nvp("structure", LandmarkEntries(structure ? data.structure : none)),
     make_nvp("control_points", LandmarkEntries(control_points ? data.control_points : none)));
}  // the archive closes the root object when it goes out of scope

}  // namespace sfm_pruning::openmvg_format
