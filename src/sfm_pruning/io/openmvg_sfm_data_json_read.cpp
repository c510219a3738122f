// sfm_data.json reader. It walks the rapidjson DOM by hand (rather than through cereal's
// JSONInputArchive) so that every variant OpenMVG has produced is accepted explicitly: free key
// order, legacy "value0" nesting, "0.1"/"0.2" files, NaN tokens, unknown fields, and so that a
// wrong type is reported with its JSON path instead of an assertion.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// cereal's header first: it sets the rapidjson configuration (throwing asserts, NaN support)
// that every translation unit using rapidjson in this library must share.
#include <rapidjson/error/en.h>

#include <cereal/archives/json.hpp>

#include "sfm_pruning/io/openmvg_sfm_data_format.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::openmvg_format {
namespace {

using JsonValue = rapidjson::Value;

// A value of the document plus the way to it, for error messages. Children point at their parent,
// so a child must not outlive the node it came from; the path is only built on error.
class JsonNode {
 public:
  JsonNode(const JsonValue& value, const std::string& source) : value_(&value), source_(&source) {}

  Error Fail(const std::string& problem) const { return FileError(Location(), problem); }
  // "<file>: <json path>", the prefix of this node's error messages.
  std::string Location() const {
    const std::string path = Path();
    return path.empty() ? *source_ : *source_ + ": " + path;
  }

  bool Has(const char* name) const { return RequireObject().FindMember(name) != value_->MemberEnd(); }
  JsonNode Child(const char* name) const {
    const auto it = RequireObject().FindMember(name);
    if (it == value_->MemberEnd()) throw Fail(std::string("missing field \"") + name + "\"");
    return JsonNode(it->value, this, name, 0);
  }
  size_t Size() const {
    if (!value_->IsArray()) throw Fail("expected array");
    return value_->Size();
  }
  JsonNode At(size_t index) const {
    return JsonNode((*value_)[static_cast<rapidjson::SizeType>(index)], this, nullptr, index);
  }

  bool IsObject() const { return value_->IsObject(); }
  uint32_t Uint() const {
    if (!value_->IsUint()) throw Fail("expected unsigned integer");
    return value_->GetUint();
  }
  double Double() const {
    if (!value_->IsNumber()) throw Fail("expected number");
    return value_->GetDouble();
  }
  bool Bool() const {
    if (!value_->IsBool()) throw Fail("expected boolean");
    return value_->GetBool();
  }
  std::string String() const {
    if (!value_->IsString()) throw Fail("expected string");
    return std::string(value_->GetString(), value_->GetStringLength());
  }
  std::vector<double> Doubles() const {
    std::vector<double> values(Size());
    for (size_t i = 0; i < values.size(); ++i) values[i] = At(i).Double();
    return values;
  }
  std::vector<double> Doubles(size_t expected) const {
    if (Size() != expected) throw Fail("expected " + std::to_string(expected) + " numbers");
    return Doubles();
  }

 private:
  JsonNode(const JsonValue& value, const JsonNode* parent, const char* name, size_t index)
      : value_(&value), parent_(parent), name_(name), index_(index), source_(parent->source_) {}

  const JsonValue& RequireObject() const {
    if (!value_->IsObject()) throw Fail("expected object");
    return *value_;
  }
  std::string Path() const {
    if (!parent_) return "";
    std::string path = parent_->Path();
    if (!name_) return path + "[" + std::to_string(index_) + "]";
    return path.empty() ? name_ : path + "." + name_;
  }

  const JsonValue* value_;
  const JsonNode* parent_ = nullptr;
  const char* name_ = nullptr;  // member name, or nullptr for an array element
  size_t index_ = 0;
  const std::string* source_;
};

Eigen::Vector3d ToVector3(const JsonNode& node) {
  const std::vector<double> v = node.Doubles(3);
  return {v[0], v[1], v[2]};
}

// Reads an OpenMVG map (an array of {"key", "value"}) in any element order.
template <typename T, typename ReadValue>
void ReadMap(const JsonNode& array, const ReadValue& read_value, std::map<IndexT, T>* out) {
  for (size_t i = 0; i < array.Size(); ++i) {
    const JsonNode entry = array.At(i);
    const JsonNode key = entry.Child("key");
    const JsonNode value = entry.Child("value");
    if (!out->emplace(key.Uint(), read_value(value)).second) {
      throw key.Fail("duplicate key " + std::to_string(key.Uint()));
    }
  }
}

// Shared pointers seen so far, by pointer id, so a later {"id": m} without data can be resolved.
template <typename T>
using PointerTable = std::map<uint32_t, T>;

// Reads a cereal ptr_wrapper: the data when the id is new, else the earlier object.
template <typename T, typename ReadData>
T ReadPointer(const JsonNode& ptr_wrapper, const ReadData& read_data, PointerTable<T>* table) {
  const JsonNode id_node = ptr_wrapper.Child("id");
  const uint32_t id = id_node.Uint();
  if (id & kNewIdFlag) {
    const JsonNode data = ptr_wrapper.Child("data");
    T object = read_data(data);
    (*table)[id & ~kNewIdFlag] = object;
    return object;
  }
  const auto it = table->find(id);
  if (it == table->end())
    throw id_node.Fail("pointer id " + std::to_string(id) + " refers to no earlier object");
  return it->second;
}

// Type name carried by a polymorphic envelope ("" for the declared type).
std::string ReadPolymorphicType(const JsonNode& value, PolymorphicIdReader* types) {
  const JsonNode id_node = value.Child("polymorphic_id");
  const uint32_t id = id_node.Uint();
  if (id == kPlainTypeId) return "";
  if (id == 0) throw id_node.Fail("null pointer");
  if (id & kNewIdFlag) {
    const std::string name = value.Child("polymorphic_name").String();
    types->Register(id, name);
    return name;
  }
  const std::string* name = types->Find(id);
  if (!name) throw id_node.Fail("polymorphic id " + std::to_string(id) + " names no earlier type");
  return *name;
}

class SfmDataJsonReader {
 public:
  explicit SfmDataJsonReader(const std::string& version) : version_(version) {}

  View ReadViewValue(const JsonNode& value) {
    std::string type;
    if (HasPolymorphicViews(version_)) {
      type = ReadPolymorphicType(value, &types_);
      if (!type.empty() && type != kViewPriorsTypeName)
        throw value.Fail("unknown view type \"" + type + "\"");
    }
    const JsonNode ptr_wrapper = value.Child("ptr_wrapper");
    return ReadPointer(
        ptr_wrapper, [&](const JsonNode& data) { return ReadViewData(data, !type.empty()); },
        &view_pointers_);
  }

  CameraIntrinsics ReadIntrinsicValue(const JsonNode& value) {
    const std::string type = ReadPolymorphicType(value, &types_);
    CameraModel model;
    if (!ModelFromTypeName(type, &model)) throw value.Fail("unknown camera model \"" + type + "\"");
    const JsonNode ptr_wrapper = value.Child("ptr_wrapper");
    return ReadPointer(
        ptr_wrapper, [&](const JsonNode& data) { return ReadIntrinsicData(data, model); },
        &intrinsic_pointers_);
  }

 private:
  static View ReadViewData(const JsonNode& data, bool with_priors) {
    View view;
    view.local_path = data.Child("local_path").String();
    view.filename = data.Child("filename").String();
    view.width = data.Child("width").Uint();
    view.height = data.Child("height").Uint();
    view.id_view = data.Child("id_view").Uint();
    view.id_intrinsic = data.Child("id_intrinsic").Uint();
    view.id_pose = data.Child("id_pose").Uint();
    if (!with_priors) return view;
    // OpenMVG omits the prior fields when the prior is disabled.
    if (data.Has("use_pose_center_prior") && data.Child("use_pose_center_prior").Bool()) {
      PoseCenterPrior prior;
      prior.weight = ToVector3(data.Child("center_weight"));
      prior.center = ToVector3(data.Child("center"));
      view.center_prior = prior;
    } else {
      view.has_prior_record = true;
    }
    return view;
  }

  static CameraIntrinsics ReadIntrinsicData(const JsonNode& data, CameraModel model) {
    // The base fields sit in a nested "value0" for spherical cameras and in OpenMVG < 2.0 files.
    const bool nested = data.Has("value0") && data.Child("value0").IsObject();
    const JsonNode base = nested ? data.Child("value0") : data;
    IntrinsicRecord record;
    record.width = base.Child("width").Uint();
    record.height = base.Child("height").Uint();
    if (IsPinholeFamily(model)) {
      record.focal_length = base.Child("focal_length").Double();
      record.principal_point = base.Child("principal_point").Doubles();
      if (const char* field = DistortionFieldName(model)) record.distortion = data.Child(field).Doubles();
      if (data.Has(kFocalLengthYField)) record.focal_length_y = data.Child(kFocalLengthYField).Double();
    }
    return FromIntrinsicRecord(model, record, data.Location());
  }

  const std::string version_;
  PolymorphicIdReader types_;
  PointerTable<View> view_pointers_;
  PointerTable<CameraIntrinsics> intrinsic_pointers_;
};

Pose ReadPose(const JsonNode& value) {
  const JsonNode rotation = value.Child("rotation");
  if (rotation.Size() != 3) throw rotation.Fail("expected 3 rows");
  Pose pose;
  for (size_t r = 0; r < 3; ++r) pose.rotation.row(r) = ToVector3(rotation.At(r)).transpose();
  pose.center = ToVector3(value.Child("center"));
  return pose;
}

Observation ReadObservation(const JsonNode& value) {
  Observation observation;
  observation.id_feat = value.Child("id_feat").Uint();
  const std::vector<double> x = value.Child("x").Doubles(2);
  observation.x = {x[0], x[1]};
  return observation;
}

Landmark ReadLandmark(const JsonNode& value) {
  Landmark landmark;
  landmark.X = ToVector3(value.Child("X"));
  ReadMap(value.Child("observations"), ReadObservation, &landmark.observations);
  return landmark;
}

}  // namespace

namespace {

SfmData ParseDocument(const std::string& text, const std::string& source, SfmDataParts parts) {
  rapidjson::Document document;
  // Iterative parsing: deeply nested garbage must not overflow the stack.
  document.Parse<rapidjson::kParseFullPrecisionFlag | rapidjson::kParseNanAndInfFlag |
                 rapidjson::kParseIterativeFlag>(text.data(), text.size());
  if (document.HasParseError()) {
    throw FileError(source, "invalid or truncated JSON at byte " + std::to_string(document.GetErrorOffset()) +
                                ": " + rapidjson::GetParseError_En(document.GetParseError()));
  }
  const JsonNode root(document, source);
  if (!root.IsObject()) throw root.Fail("expected a JSON object at the top level");

  SfmData data;
  const std::string version = root.Child("sfm_data_version").String();
  data.root_path = root.Child("root_path").String();
  SfmDataJsonReader reader(version);
  if (HasParts(parts, SfmDataParts::kViews)) {
    ReadMap(
        root.Child("views"), [&](const JsonNode& v) { return reader.ReadViewValue(v); }, &data.views);
  }
  if (HasParts(parts, SfmDataParts::kIntrinsics)) {
    ReadMap(
        root.Child("intrinsics"), [&](const JsonNode& v) { return reader.ReadIntrinsicValue(v); },
        &data.intrinsics);
  }
  if (HasParts(parts, SfmDataParts::kExtrinsics)) ReadMap(root.Child("extrinsics"), ReadPose, &data.poses);
  if (HasParts(parts, SfmDataParts::kStructure))
    ReadMap(root.Child("structure"), ReadLandmark, &data.structure);
  if (HasParts(parts, SfmDataParts::kControlPoints) && HasControlPoints(version)) {
    ReadMap(root.Child("control_points"), ReadLandmark, &data.control_points);
  }
  return data;
}

}  // namespace

SfmData ParseSfmDataJson(const std::string& text, const std::string& source, SfmDataParts parts) {
  try {
    return ParseDocument(text, source, parts);
  } catch (const cereal::Exception& e) {  // a rapidjson assertion: a bug, but still bad input
    throw FileError(source, e.what());
  }
}

}  // namespace sfm_pruning::openmvg_format
