// Where a camera's initial focal length comes from, and whether it can be trusted (COLMAP's
// prior_focal_length flag): a focal given by the user, read from a K file or derived from EXIF is
// trusted; the default guess 1.2 * max(width, height) (COLMAP's) is not, and is what the focal
// calibration of the GLOBAL engine has to correct.
#pragma once

#include <optional>
#include <string>

#include "sfm_pruning/features/exif_metadata.hpp"

namespace sfm_pruning {

enum class FocalSource {
  kUserFocal,        // --focal
  kKFile,            // a 3x3 K matrix file
  kExifSensorWidth,  // EXIF focal (mm) and a sensor width given by the user
  kExif35mm,         // EXIF FocalLengthIn35mmFilm, scaled by the image diagonal
  kExifFocalPlane,   // EXIF focal (mm) and FocalPlaneXResolution (the sensor width)
  kDefaultGuess,     // default_focal_factor * max(width, height)
};

// Stable lower-case names ("user_focal", "k_file", "exif_sensor_width", "exif_35mm",
// "exif_focal_plane", "default_guess"), used in files and messages.
std::string FocalSourceName(FocalSource source);
// Inverse of FocalSourceName; nullopt for an unknown name.
std::optional<FocalSource> FocalSourceFromName(const std::string& name);
// Every source except kDefaultGuess.
inline bool IsFocalTrusted(FocalSource source) { return source != FocalSource::kDefaultGuess; }

// The diagonal of a 36 x 24 mm frame, the reference of FocalLengthIn35mmFilm (CIPA DC-008).
inline constexpr double kFullFrameDiagonalMm = 43.266615305567875;
// COLMAP's prior for a camera without EXIF: 1.2 * max(width, height).
inline constexpr double kDefaultFocalFactor = 1.2;

struct FocalPriorOptions {
  double sensor_width_mm = 0.0;  // > 0: used with the EXIF focal in mm before anything else
  double default_focal_factor = kDefaultFocalFactor;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct FocalPrior {
  double focal_px = 0.0;
  FocalSource source = FocalSource::kDefaultGuess;
};

// The focal length in pixels of an image of width x height from its EXIF (may be null), in this
// order: focal mm + options.sensor_width_mm; 35 mm equivalent; focal mm + focal-plane
// resolution; the default guess.
FocalPrior FocalFromExif(const ExifMetadata* exif, uint32_t width, uint32_t height, const FocalPriorOptions& options);

}  // namespace sfm_pruning
