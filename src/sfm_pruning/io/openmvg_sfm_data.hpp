// OpenMVG 2.x scene files: sfm_data.json (cereal JSON) and sfm_data.bin (cereal PortableBinary).
//
// Files are data-compatible with OpenMVG: the writer emits what OpenMVG's own cereal archive would
// (version "0.3", all seven sections, maps as [{"key", "value"}] arrays sorted by key, the
// polymorphic envelope with per-archive type and pointer ids, 4-space indent, rapidjson number
// formatting), so stock OpenMVG tools load our files. The reader accepts every variant OpenMVG
// 2.1 and older versions produce: versions "0.1" (no control_points), "0.2" (non-polymorphic
// views) and "0.3"; legacy "value0" nesting of pinhole_brown_t2 / fisheye; NaN / Infinity tokens;
// keys and array elements in any order; unknown extra fields (ignored).
//
// Camera models map one to one onto OpenMVG's pinhole, pinhole_radial_k1, pinhole_radial_k3,
// pinhole_brown_t2, fisheye and spherical, except:
//   kPinholeFxFy (COLMAP's PINHOLE with fx != fy) has no OpenMVG counterpart. In JSON it is written
//   as a "pinhole" with focal_length = fx and an extra field "focal_length_y" = fy, which OpenMVG
//   ignores (it then sees a pinhole camera with focal fx). On read, a "pinhole" whose
//   focal_length_y differs from focal_length becomes kPinholeFxFy; an equal (or absent) one gives
//   kPinhole. The binary format has no room for extra fields: writing a kPinholeFxFy with fx != fy
//   to .bin throws Error.
//
// View priors: a View with center_prior (or has_prior_record) is written as OpenMVG's
// "view_priors". In JSON the prior fields appear only when the prior is enabled (as OpenMVG
// does); in .bin they are always written (use_pose_center_prior tells whether it is enabled),
// because a binary reader cannot skip absent fields.
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// The sections of an sfm_data file (OpenMVG's ESfM_Data flags, same values).
enum class SfmDataParts : unsigned {
  kViews = 1,
  kExtrinsics = 2,
  kIntrinsics = 4,
  kStructure = 8,
  kControlPoints = 16,
  kAll = 31,
};

constexpr SfmDataParts operator|(SfmDataParts a, SfmDataParts b) {
  return static_cast<SfmDataParts>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
constexpr SfmDataParts operator&(SfmDataParts a, SfmDataParts b) {
  return static_cast<SfmDataParts>(static_cast<unsigned>(a) & static_cast<unsigned>(b));
}
constexpr SfmDataParts operator~(SfmDataParts a) {
  return static_cast<SfmDataParts>(~static_cast<unsigned>(a) & static_cast<unsigned>(SfmDataParts::kAll));
}
inline SfmDataParts& operator|=(SfmDataParts& a, SfmDataParts b) { return a = a | b; }
inline SfmDataParts& operator&=(SfmDataParts& a, SfmDataParts b) { return a = a & b; }
// True when every section of `wanted` is in `parts`.
constexpr bool HasParts(SfmDataParts parts, SfmDataParts wanted) { return (parts & wanted) == wanted; }

// Reads an sfm_data file; the format follows the extension (.json or .bin). Only the requested
// sections are read (in JSON the others may be absent); sections not requested stay empty.
// When views are read, the result is checked with ValidateSfmData (orphan intrinsics or poses,
// observations of missing views are errors, as in OpenMVG).
// Throws Error with a one-line message naming the file on any problem.
SfmData ReadSfmData(const std::filesystem::path& path, SfmDataParts parts = SfmDataParts::kAll);

// Writes an sfm_data file (.json or .bin by extension) atomically. Sections not requested are
// written as empty arrays, as OpenMVG does. Throws Error naming the file on failure.
void WriteSfmData(const SfmData& data, const std::filesystem::path& path,
                  SfmDataParts parts = SfmDataParts::kAll);

}  // namespace sfm_pruning
