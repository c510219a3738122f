// Internal to io/openmvg_sfm_data*: the facts of OpenMVG's sfm_data layout shared by the JSON
// and binary readers and writers (FORMATS.md §1), so each rule lives in one place.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/sfm/camera_intrinsics.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning::openmvg_format {

// cereal's id flags. kNewIdFlag (MSB) marks the first occurrence of a polymorphic type (its name
// follows) or of a shared pointer (its data follows); kPlainTypeId says the object has the
// declared type (a plain View), so no type registry entry is involved.
inline constexpr uint32_t kNewIdFlag = 0x80000000u;
inline constexpr uint32_t kPlainTypeId = 0x40000000u;

inline constexpr char kWrittenVersion[] = "0.3";
inline constexpr char kViewPriorsTypeName[] = "view_priors";
inline constexpr char kFocalLengthYField[] = "focal_length_y";  // our kPinholeFxFy extension

// Version gates. OpenMVG compares version strings lexicographically; so do we.
inline bool HasPolymorphicViews(const std::string& version) { return version >= "0.3"; }
inline bool HasControlPoints(const std::string& version) { return version != "0.1"; }

// What precedes the data of a polymorphic shared pointer in the archive.
struct PolymorphicEnvelope {
  uint32_t type_id = kPlainTypeId;
  std::string new_type_name;  // written after type_id only on the type's first use; else empty
  uint32_t pointer_id = 0;    // always a new pointer (flagged), so the data follows
};

// Numbers polymorphic types and shared pointers over one output archive, as cereal does: the
// n-th distinct type gets n (with kNewIdFlag and its name on first use), pointers count from 1.
class PolymorphicIdWriter {
 public:
  // Envelope of the next object; an empty `type_name` means the declared type (plain View).
  PolymorphicEnvelope Next(const std::string& type_name);

 private:
  std::map<std::string, uint32_t> type_ids_;
  uint32_t pointer_count_ = 0;
};

// The reader's side of the type registry: names registered by flagged ids, looked up by the
// small id of later objects.
class PolymorphicIdReader {
 public:
  // Registers `name` for a flagged id. Returns false for an unflagged id.
  bool Register(uint32_t id, const std::string& name);
  // Name for an unflagged id, nullptr when it was never registered.
  const std::string* Find(uint32_t id) const;

 private:
  std::map<uint32_t, std::string> names_;
};

// An intrinsic in OpenMVG's terms: its polymorphic type name and its fields.
struct IntrinsicRecord {
  std::string type_name;
  uint32_t width = 0;
  uint32_t height = 0;
  double focal_length = 0.0;
  std::vector<double> principal_point;   // [cx, cy]
  std::vector<double> distortion;        // the model's disto_* / fisheye vector
  std::optional<double> focal_length_y;  // kPinholeFxFy extension
};

// Name of the distortion field of an OpenMVG type ("disto_k3", "fisheye", ...), nullptr for
// types without one; throws nothing.
const char* DistortionFieldName(CameraModel model);

IntrinsicRecord ToIntrinsicRecord(const CameraIntrinsics& intrinsic);
// Maps an OpenMVG type name to our model; kPinholeFxFy is never named in files (returns false).
bool ModelFromTypeName(const std::string& type_name, CameraModel* model);
// Builds the intrinsic; throws FileError(where, ...) when a vector has the wrong length.
CameraIntrinsics FromIntrinsicRecord(CameraModel model, const IntrinsicRecord& record,
                                     const std::string& where);

// Whether a view is written as OpenMVG's "view_priors" subtype.
inline bool IsViewPriors(const View& view) { return view.center_prior.has_value() || view.has_prior_record; }
// Polymorphic type name of a view for PolymorphicIdWriter::Next ("" for a plain View).
inline std::string ViewTypeName(const View& view) { return IsViewPriors(view) ? kViewPriorsTypeName : ""; }

// Format back ends; `source` names the file in error messages.
SfmData ParseSfmDataJson(const std::string& text, const std::string& source, SfmDataParts parts);
void WriteSfmDataJson(const SfmData& data, SfmDataParts parts, std::ostream& out);
SfmData ParseSfmDataBinary(const std::string& bytes, const std::string& source, SfmDataParts parts);
void WriteSfmDataBinary(const SfmData& data, SfmDataParts parts, std::ostream& out,
                        const std::string& source);

}  // namespace sfm_pruning::openmvg_format
