#include "sfm_pruning/features/focal_prior.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

constexpr std::pair<FocalSource, const char*> kNames[] = {
    {FocalSource::kUserFocal, "user_focal"},           {FocalSource::kKFile, "k_file"},
    {FocalSource::kExifSensorWidth, "exif_sensor_width"}, {FocalSource::kExif35mm, "exif_35mm"},
    {FocalSource::kExifFocalPlane, "exif_focal_plane"},   {FocalSource::kDefaultGuess, "default_guess"},
};

// A focal of more than this many image sides is no lens (a field of view under 0.6 degrees).
constexpr double kMaxExifFocalSides = 100.0;

}  // namespace

std::string FocalSourceName(FocalSource source) {
  for (const auto& [value, name] : kNames) {
    if (value == source) return name;
  }
  return "unknown";
}

std::optional<FocalSource> FocalSourceFromName(const std::string& name) {
  for (const auto& [value, known] : kNames) {
    if (name == known) return value;
  }
  return std::nullopt;
}

FocalPrior FocalFromExif(const ExifMetadata* exif, uint32_t width, uint32_t height, const FocalPriorOptions& options) {
  options.Check();
  const double max_side = std::max(width, height);
  // A tag that gives no real lens (0, NaN, 65535 mm) falls through to the next source: the focal
  // must be one that IntrinsicsProblem (sfm/sfm_data.hpp) accepts, else the whole run would stop.
  const auto plausible = [&](double focal_px) { return focal_px > 0.0 && focal_px <= kMaxExifFocalSides * max_side; };
  if (exif != nullptr) {
    if (exif->focal_mm && options.sensor_width_mm > 0.0) {
      const double focal = *exif->focal_mm * max_side / options.sensor_width_mm;
      if (plausible(focal)) return {focal, FocalSource::kExifSensorWidth};
    }
    if (exif->focal_35mm) {
      // The 35 mm equivalent keeps the field of view along the diagonal.
      const double diagonal_px = std::hypot(static_cast<double>(width), static_cast<double>(height));
      const double focal = *exif->focal_35mm * diagonal_px / kFullFrameDiagonalMm;
      if (plausible(focal)) return {focal, FocalSource::kExif35mm};
    }
    if (exif->focal_mm && exif->focal_plane_x_res_mm) {
      // Pixels per mm along the sensor's long side at the recorded resolution (PixelXDimension
      // when given), scaled to this image: it may have been resized or rotated after capture.
      const double recorded_width = exif->pixel_x_dimension.value_or(max_side);
      const double px_per_mm = *exif->focal_plane_x_res_mm * max_side / recorded_width;
      const double focal = *exif->focal_mm * px_per_mm;
      if (plausible(focal)) return {focal, FocalSource::kExifFocalPlane};
    }
  }
  return {options.default_focal_factor * max_side, FocalSource::kDefaultGuess};
}

void FocalPriorOptions::Check() const {
  // 0: no sensor width (the EXIF focal in mm is used through the other sources only). The bound
  // is 10 m, far past any camera's sensor.
  if (sensor_width_mm != 0.0) {
    RequirePositiveAtMost(sensor_width_mm, 1e4, "FocalPriorOptions::sensor_width_mm (or 0: none)");
  }
  // A focal over 1000 image sides is one IntrinsicsProblem (sfm/sfm_data.hpp) refuses.
  RequirePositiveAtMost(default_focal_factor, 1000.0, "FocalPriorOptions::default_focal_factor");
}

}  // namespace sfm_pruning
