// sfm_data.bin: cereal's PortableBinary layout (FORMATS.md §1.10), written and read by hand so
// that every read is bounds-checked (a truncated or corrupt file is an Error, never a crash or a
// huge allocation). Layout: 1 byte endianness (1 = little), then the same sequence of fields as
// the JSON form without names: strings and containers carry a uint64 length, ids are uint32,
// numbers are IEEE doubles, polymorphic ids and pointer ids as in JSON.
#include <cstring>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "sfm_pruning/io/openmvg_sfm_data_format.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::openmvg_format {
namespace {

inline constexpr uint8_t kLittleEndian = 1;
inline constexpr uint8_t kBigEndian = 0;

class BinaryWriter {
 public:
  void U8(uint8_t v) { bytes_.push_back(static_cast<char>(v)); }
  void U32(uint32_t v) { Unsigned(v, 4); }
  void U64(uint64_t v) { Unsigned(v, 8); }
  void F64(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    U64(bits);
  }
  void String(const std::string& s) {
    U64(s.size());
    bytes_ += s;
  }
  void Doubles(const std::vector<double>& values) {
    U64(values.size());
    for (double v : values) F64(v);
  }
  void Vector(const Eigen::Vector3d& v) { Doubles({v.x(), v.y(), v.z()}); }
  const std::string& bytes() const { return bytes_; }

 private:
  // Little endian whatever the host.
  void Unsigned(uint64_t v, int size) {
    for (int i = 0; i < size; ++i) bytes_.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  }
  std::string bytes_;
};

class BinaryReader {
 public:
  BinaryReader(const std::string& bytes, const std::string& source) : bytes_(bytes), source_(source) {
    const uint8_t endianness = U8("endianness flag");
    if (endianness != kLittleEndian && endianness != kBigEndian) {
      throw FileError(
          source_, "not a cereal portable binary file (endianness flag " + std::to_string(endianness) + ")");
    }
    big_endian_ = endianness == kBigEndian;
  }

  Error Fail(const std::string& problem) const {
    return FileError(source_, problem + " (at byte " + std::to_string(offset_) + ")");
  }

  uint8_t U8(const char* what) { return static_cast<uint8_t>(Unsigned(1, what)); }
  uint32_t U32(const char* what) { return static_cast<uint32_t>(Unsigned(4, what)); }
  double F64(const char* what) {
    const uint64_t bits = Unsigned(8, what);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  bool Bool(const char* what) {
    const uint8_t v = U8(what);
    if (v > 1) throw Fail(std::string(what) + ": invalid boolean " + std::to_string(v));
    return v == 1;
  }
  // A container length, checked against the bytes left so corrupt lengths fail fast.
  size_t Count(const char* what, size_t min_bytes_per_element) {
    const uint64_t count = Unsigned(8, what);
    if (count > (bytes_.size() - offset_) / min_bytes_per_element) {
      throw Fail(std::string("truncated file: ") + what + " announces " + std::to_string(count) +
                 " elements");
    }
    return static_cast<size_t>(count);
  }
  std::string String(const char* what) {
    const size_t size = Count(what, 1);
    std::string s = bytes_.substr(offset_, size);
    offset_ += size;
    return s;
  }
  std::vector<double> Doubles(const char* what) {
    std::vector<double> values(Count(what, sizeof(double)));
    for (double& v : values) v = F64(what);
    return values;
  }
  std::vector<double> Doubles(const char* what, size_t expected) {
    std::vector<double> values = Doubles(what);
    if (values.size() != expected) {
      throw Fail(std::string(what) + ": expected " + std::to_string(expected) + " numbers, got " +
                 std::to_string(values.size()));
    }
    return values;
  }
  Eigen::Vector3d Vector(const char* what) {
    const std::vector<double> v = Doubles(what, 3);
    return {v[0], v[1], v[2]};
  }
  bool AtEnd() const { return offset_ == bytes_.size(); }
  const std::string& source() const { return source_; }

 private:
  uint64_t Unsigned(int size, const char* what) {
    if (bytes_.size() - offset_ < static_cast<size_t>(size)) {
      throw Fail(std::string("truncated file while reading ") + what);
    }
    uint64_t v = 0;
    for (int i = 0; i < size; ++i) {
      const uint64_t byte = static_cast<unsigned char>(bytes_[offset_ + i]);
      v |= byte << (8 * (big_endian_ ? size - 1 - i : i));
    }
    offset_ += size;
    return v;
  }

  const std::string& bytes_;
  const std::string& source_;
  size_t offset_ = 0;
  bool big_endian_ = false;
};

// ---------------------------------------------------------------------------------------------
// Writing

void WriteEnvelope(const PolymorphicEnvelope& envelope, BinaryWriter* out) {
  out->U32(envelope.type_id);
  if (!envelope.new_type_name.empty()) out->String(envelope.new_type_name);
  out->U32(envelope.pointer_id);
}

void WriteView(const View& view, BinaryWriter* out) {
  out->String(view.local_path);
  out->String(view.filename);
  for (uint32_t v : {view.width, view.height, view.id_view, view.id_intrinsic, view.id_pose}) out->U32(v);
  if (!IsViewPriors(view)) return;
  // Always all three fields: a binary reader cannot tell whether optional fields are present.
  const PoseCenterPrior prior = view.center_prior.value_or(PoseCenterPrior());
  out->U8(view.center_prior.has_value() ? 1 : 0);
  out->Vector(prior.weight);
  out->Vector(prior.center);
}

void WriteIntrinsic(CameraModel model, const IntrinsicRecord& record, BinaryWriter* out) {
  out->U32(record.width);
  out->U32(record.height);
  if (!IsPinholeFamily(model)) return;
  out->F64(record.focal_length);
  out->Doubles(record.principal_point);
  if (DistortionFieldName(model)) out->Doubles(record.distortion);
}

void WriteLandmarks(const std::map<IndexT, Landmark>& landmarks, BinaryWriter* out) {
  out->U64(landmarks.size());
  for (const auto& [id, landmark] : landmarks) {
    out->U32(id);
    out->Vector(landmark.X);
    out->U64(landmark.observations.size());
    for (const auto& [view_id, observation] : landmark.observations) {
      out->U32(view_id);
      out->U32(observation.id_feat);
      out->Doubles({observation.x.x(), observation.x.y()});
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Reading

class SfmDataBinaryReader {
 public:
  SfmDataBinaryReader(BinaryReader* in, const std::string& version) : in_(*in), version_(version) {}

  View ReadViewValue() {
    std::string type;
    if (HasPolymorphicViews(version_)) {
      type = ReadPolymorphicType();
      if (!type.empty() && type != kViewPriorsTypeName) throw in_.Fail("unknown view type \"" + type + "\"");
    }
    return ReadPointer([&] { return ReadViewData(!type.empty()); }, &view_pointers_);
  }

  CameraIntrinsics ReadIntrinsicValue() {
    const std::string type = ReadPolymorphicType();
    CameraModel model;
    if (!ModelFromTypeName(type, &model)) throw in_.Fail("unknown camera model \"" + type + "\"");
    return ReadPointer([&] { return ReadIntrinsicData(model); }, &intrinsic_pointers_);
  }

 private:
  std::string ReadPolymorphicType() {
    const uint32_t id = in_.U32("polymorphic_id");
    if (id == kPlainTypeId) return "";
    if (id == 0) throw in_.Fail("null pointer");
    if (id & kNewIdFlag) {
      const std::string name = in_.String("polymorphic_name");
      types_.Register(id, name);
      return name;
    }
    const std::string* name = types_.Find(id);
    if (!name) throw in_.Fail("polymorphic id " + std::to_string(id) + " names no earlier type");
    return *name;
  }

  template <typename T, typename ReadData>
  T ReadPointer(const ReadData& read_data, std::map<uint32_t, T>* table) {
    const uint32_t id = in_.U32("pointer id");
    if (id & kNewIdFlag) return (*table)[id & ~kNewIdFlag] = read_data();
    const auto it = table->find(id);
    if (it == table->end())
      throw in_.Fail("pointer id " + std::to_string(id) + " refers to no earlier object");
    return it->second;
  }

  View ReadViewData(bool with_priors) {
    View view;
    view.local_path = in_.String("view local_path");
    view.filename = in_.String("view filename");
    view.width = in_.U32("view width");
    view.height = in_.U32("view height");
    view.id_view = in_.U32("id_view");
    view.id_intrinsic = in_.U32("id_intrinsic");
    view.id_pose = in_.U32("id_pose");
    if (!with_priors) return view;
    const bool enabled = in_.Bool("use_pose_center_prior");
    PoseCenterPrior prior;
    prior.weight = in_.Vector("center_weight");
    prior.center = in_.Vector("center");
    if (enabled) {
      view.center_prior = prior;
    } else {
      view.has_prior_record = true;
    }
    return view;
  }

  CameraIntrinsics ReadIntrinsicData(CameraModel model) {
    IntrinsicRecord record;
    record.width = in_.U32("intrinsic width");
    record.height = in_.U32("intrinsic height");
    if (IsPinholeFamily(model)) {
      record.focal_length = in_.F64("focal_length");
      record.principal_point = in_.Doubles("principal_point");
      if (const char* field = DistortionFieldName(model)) record.distortion = in_.Doubles(field);
    }
    return FromIntrinsicRecord(model, record, in_.source() + ": intrinsic");
  }

  BinaryReader& in_;
  const std::string version_;
  PolymorphicIdReader types_;
  std::map<uint32_t, View> view_pointers_;
  std::map<uint32_t, CameraIntrinsics> intrinsic_pointers_;
};

// Reads a map section; smallest possible entry size guards the count.
template <typename T, typename ReadValue>
void ReadMap(BinaryReader* in, const char* what, size_t min_entry_bytes, const ReadValue& read_value,
             std::map<IndexT, T>* out) {
  const size_t count = in->Count(what, min_entry_bytes);
  for (size_t i = 0; i < count; ++i) {
    const IndexT key = in->U32(what);
    if (!out->emplace(key, read_value()).second) {
      throw in->Fail(std::string(what) + ": duplicate key " + std::to_string(key));
    }
  }
}

Pose ReadPose(BinaryReader* in) {
  Pose pose;
  if (in->Count("rotation", 8) != 3) throw in->Fail("rotation: expected 3 rows");
  for (int r = 0; r < 3; ++r) pose.rotation.row(r) = in->Vector("rotation").transpose();
  pose.center = in->Vector("center");
  return pose;
}

Landmark ReadLandmark(BinaryReader* in) {
  Landmark landmark;
  landmark.X = in->Vector("landmark X");
  ReadMap(
      in, "observations", 4 + 4 + 8,
      [&] {
        Observation observation;
        observation.id_feat = in->U32("id_feat");
        const std::vector<double> x = in->Doubles("observation x", 2);
        observation.x = {x[0], x[1]};
        return observation;
      },
      &landmark.observations);
  return landmark;
}

// Minimal encoded sizes of map entries (key + the smallest value), to reject absurd counts.
inline constexpr size_t kMinViewEntryBytes = 4 + 4 + 4;
inline constexpr size_t kMinIntrinsicEntryBytes = 4 + 4 + 4 + 8;
inline constexpr size_t kMinPoseEntryBytes = 4 + 8 + 8;
inline constexpr size_t kMinLandmarkEntryBytes = 4 + 8 + 8;

}  // namespace

void WriteSfmDataBinary(const SfmData& data, SfmDataParts parts, std::ostream& out,
                        const std::string& source) {
  BinaryWriter w;
  w.U8(kLittleEndian);
  w.String(kWrittenVersion);
  w.String(data.root_path);
  // Unrequested sections are written empty, as OpenMVG does.
  const std::map<IndexT, View> no_views;
  const std::map<IndexT, CameraIntrinsics> no_intrinsics;
  const std::map<IndexT, Pose> no_poses;
  const auto& views = HasParts(parts, SfmDataParts::kViews) ? data.views : no_views;
  const auto& intrinsics = HasParts(parts, SfmDataParts::kIntrinsics) ? data.intrinsics : no_intrinsics;
  const auto& poses = HasParts(parts, SfmDataParts::kExtrinsics) ? data.poses : no_poses;

  PolymorphicIdWriter ids;  // views first, then intrinsics, as cereal numbers them
  w.U64(views.size());
  for (const auto& [id, view] : views) {
    w.U32(id);
    WriteEnvelope(ids.Next(ViewTypeName(view)), &w);
    WriteView(view, &w);
  }
  w.U64(intrinsics.size());
  for (const auto& [id, intrinsic] : intrinsics) {
    const IntrinsicRecord record = ToIntrinsicRecord(intrinsic);
    if (record.focal_length_y && *record.focal_length_y != record.focal_length) {
      throw FileError(source, "intrinsic " + std::to_string(id) +
                                  " has fx != fy, which OpenMVG's binary format cannot store; write .json");
    }
    w.U32(id);
    WriteEnvelope(ids.Next(record.type_name), &w);
    WriteIntrinsic(intrinsic.model(), record, &w);
  }
  w.U64(poses.size());
  for (const auto& [id, pose] : poses) {
    w.U32(id);
    w.U64(3);
    for (int r = 0; r < 3; ++r) w.Vector(pose.rotation.row(r).transpose());
    w.Vector(pose.center);
  }
  const std::map<IndexT, Landmark> none;
  WriteLandmarks(HasParts(parts, SfmDataParts::kStructure) ? data.structure : none, &w);
  WriteLandmarks(HasParts(parts, SfmDataParts::kControlPoints) ? data.control_points : none, &w);
  out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
}

SfmData ParseSfmDataBinary(const std::string& bytes, const std::string& source, SfmDataParts parts) {
  BinaryReader in(bytes, source);
  SfmData all;
  const std::string version = in.String("sfm_data_version");
  all.root_path = in.String("root_path");
  // Every section must be read to reach the next one; unrequested ones are dropped at the end.
  SfmDataBinaryReader reader(&in, version);
  ReadMap(
      &in, "views", kMinViewEntryBytes, [&] { return reader.ReadViewValue(); }, &all.views);
  ReadMap(
      &in, "intrinsics", kMinIntrinsicEntryBytes, [&] { return reader.ReadIntrinsicValue(); },
      &all.intrinsics);
  ReadMap(
      &in, "extrinsics", kMinPoseEntryBytes, [&] { return ReadPose(&in); }, &all.poses);
  ReadMap(
      &in, "structure", kMinLandmarkEntryBytes, [&] { return ReadLandmark(&in); }, &all.structure);
  if (HasControlPoints(version)) {
    ReadMap(
        &in, "control_points", kMinLandmarkEntryBytes, [&] { return ReadLandmark(&in); },
        &all.control_points);
  }
  if (!in.AtEnd()) throw in.Fail("unexpected data after the last section");

  SfmData data;
  data.root_path = all.root_path;
  if (HasParts(parts, SfmDataParts::kViews)) data.views = std::move(all.views);
  if (HasParts(parts, SfmDataParts::kIntrinsics)) data.intrinsics = std::move(all.intrinsics);
  if (HasParts(parts, SfmDataParts::kExtrinsics)) data.poses = std::move(all.poses);
  if (HasParts(parts, SfmDataParts::kStructure)) data.structure = std::move(all.structure);
  if (HasParts(parts, SfmDataParts::kControlPoints)) data.control_points = std::move(all.control_points);
  return data;
}

}  // namespace sfm_pruning::openmvg_format
