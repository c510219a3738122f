#include "sfm_pruning/features/exif_metadata.hpp"

#include <libexif/exif-data.h>

#include <memory>

namespace sfm_pruning {
namespace {

struct ExifDataDeleter {
  void operator()(ExifData* data) const { exif_data_unref(data); }
};

ExifEntry* FindEntry(ExifData* data, ExifIfd ifd, ExifTag tag) { return exif_content_get_entry(data->ifd[ifd], tag); }

std::string AsciiValue(ExifData* data, ExifIfd ifd, ExifTag tag) {
  ExifEntry* entry = FindEntry(data, ifd, tag);
  if (entry == nullptr || entry->format != EXIF_FORMAT_ASCII || entry->data == nullptr) return {};
  std::string value(reinterpret_cast<const char*>(entry->data), entry->size);
  value = value.substr(0, value.find('\0'));
  while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.pop_back();
  return value;
}

// A positive numeric value of a RATIONAL, SHORT or LONG entry, or nullopt.
std::optional<double> PositiveNumber(ExifData* data, ExifIfd ifd, ExifTag tag) {
  ExifEntry* entry = FindEntry(data, ifd, tag);
  if (entry == nullptr || entry->data == nullptr || entry->components < 1) return std::nullopt;
  const ExifByteOrder order = exif_data_get_byte_order(data);
  double value = 0.0;
  switch (entry->format) {
    case EXIF_FORMAT_RATIONAL: {
      if (entry->size < 8) return std::nullopt;
      const ExifRational r = exif_get_rational(entry->data, order);
      if (r.denominator == 0) return std::nullopt;
      value = static_cast<double>(r.numerator) / r.denominator;
      break;
    }
    case EXIF_FORMAT_SHORT:
      if (entry->size < 2) return std::nullopt;
      value = exif_get_short(entry->data, order);
      break;
    case EXIF_FORMAT_LONG:
      if (entry->size < 4) return std::nullopt;
      value = exif_get_long(entry->data, order);
      break;
    default:
      return std::nullopt;
  }
  if (!(value > 0.0)) return std::nullopt;
  return value;
}

}  // namespace

std::string ExifMetadata::Body() const {
  if (make.empty()) return model;
  if (model.empty()) return make;
  return make + " " + model;
}

std::optional<ExifMetadata> ReadExifMetadata(const std::filesystem::path& path) {
  std::unique_ptr<ExifData, ExifDataDeleter> data(exif_data_new_from_file(path.c_str()));
  if (!data) return std::nullopt;
  ExifMetadata metadata;
  metadata.make = AsciiValue(data.get(), EXIF_IFD_0, EXIF_TAG_MAKE);
  metadata.model = AsciiValue(data.get(), EXIF_IFD_0, EXIF_TAG_MODEL);
  metadata.focal_mm = PositiveNumber(data.get(), EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH);
  metadata.focal_35mm = PositiveNumber(data.get(), EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH_IN_35MM_FILM);
  metadata.pixel_x_dimension = PositiveNumber(data.get(), EXIF_IFD_EXIF, EXIF_TAG_PIXEL_X_DIMENSION);
  const std::optional<double> resolution =
      PositiveNumber(data.get(), EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_X_RESOLUTION);
  const std::optional<double> unit =
      PositiveNumber(data.get(), EXIF_IFD_EXIF, EXIF_TAG_FOCAL_PLANE_RESOLUTION_UNIT);
  if (resolution) {
    // ResolutionUnit: 2 = inch (the EXIF default when absent), 3 = centimetre, 4 = millimetre.
    const double unit_mm = !unit || *unit == 2 ? 25.4 : *unit == 3 ? 10.0 : *unit == 4 ? 1.0 : 0.0;
    if (unit_mm > 0.0) metadata.focal_plane_x_res_mm = *resolution / unit_mm;
  }
  return metadata;
}

}  // namespace sfm_pruning
