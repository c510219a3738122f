// The EXIF fields the front end needs to guess a camera's focal length in pixels: the camera
// body (make, model), the focal length in millimetres, its 35 mm equivalent and the focal-plane
// resolution (which gives the sensor width). Read with libexif from JPEG (and other files with
// an EXIF block); PNGs and stripped JPEGs have none.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace sfm_pruning {

struct ExifMetadata {
  std::string make;   // "" when absent; trailing spaces removed
  std::string model;
  std::optional<double> focal_mm;              // FocalLength
  std::optional<double> focal_35mm;            // FocalLengthIn35mmFilm (0 = unknown -> absent)
  std::optional<double> focal_plane_x_res_mm;  // FocalPlaneXResolution in pixels per millimetre
  std::optional<double> pixel_x_dimension;     // PixelXDimension: the width that resolution refers to

  // "make model", or "" when both are absent.
  std::string Body() const;
};

// The metadata of `path`, or nullopt when the file has no EXIF block (or is not a file libexif
// understands). Never throws for a file without EXIF; a value that is present but malformed
// (zero denominator, negative) is treated as absent.
std::optional<ExifMetadata> ReadExifMetadata(const std::filesystem::path& path);

}  // namespace sfm_pruning
