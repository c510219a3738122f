// EXIF parsing on a JPEG written here with a hand-made EXIF block, and the focal it gives.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "sfm_pruning/features/exif_metadata.hpp"
#include "sfm_pruning/features/focal_prior.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// A little-endian TIFF block: IFD0 {Make, Model, ExifIFD pointer}, Exif IFD {FocalLength,
// FocalLengthIn35mmFilm, FocalPlaneXResolution, FocalPlaneResolutionUnit}.
struct TiffWriter {
  std::vector<uint8_t> bytes;
  void U16(uint32_t v) { bytes.push_back(v & 0xff), bytes.push_back((v >> 8) & 0xff); }
  void U32(uint32_t v) { U16(v & 0xffff), U16(v >> 16); }
  void Put16(size_t at, uint32_t v) { bytes[at] = v & 0xff, bytes[at + 1] = (v >> 8) & 0xff; }
  void Put32(size_t at, uint32_t v) { Put16(at, v & 0xffff), Put16(at + 2, v >> 16); }
};

struct ExifFields {
  std::string make = "Canon";
  std::string model = "EOS 5D";
  uint32_t focal_num = 35, focal_den = 1;  // mm
  uint32_t focal35 = 50;                   // 0: tag absent
  uint32_t plane_res_num = 0, plane_res_den = 1;  // pixels per inch; 0: tags absent
};

std::vector<uint8_t> MakeExifBlock(const ExifFields& f) {
  TiffWriter w;
  w.bytes = {'I', 'I', 42, 0};
  w.U32(8);  // IFD0 offset
  // IFD0: 3 entries; data area after it.
  const size_t ifd0 = w.bytes.size();
  const uint32_t ifd0_size = 2 + 3 * 12 + 4;
  uint32_t data = static_cast<uint32_t>(ifd0 + ifd0_size);
  const uint32_t make_at = data;
  data += static_cast<uint32_t>(f.make.size() + 1);
  const uint32_t model_at = data;
  data += static_cast<uint32_t>(f.model.size() + 1);
  const uint32_t exif_ifd = data;
  w.U16(3);
  w.U16(0x010f), w.U16(2), w.U32(static_cast<uint32_t>(f.make.size() + 1)), w.U32(make_at);
  w.U16(0x0110), w.U16(2), w.U32(static_cast<uint32_t>(f.model.size() + 1)), w.U32(model_at);
  w.U16(0x8769), w.U16(4), w.U32(1), w.U32(exif_ifd);
  w.U32(0);  // no next IFD
  for (char c : f.make) w.bytes.push_back(static_cast<uint8_t>(c));
  w.bytes.push_back(0);
  for (char c : f.model) w.bytes.push_back(static_cast<uint8_t>(c));
  w.bytes.push_back(0);
  // Exif IFD: entries sorted by tag.
  struct Entry { uint16_t tag, type; uint32_t count, value; bool rational; uint32_t num, den; };
  std::vector<Entry> entries;
  entries.push_back({0x920a, 5, 1, 0, true, f.focal_num, f.focal_den});
  if (f.plane_res_num > 0) {
    entries.push_back({0xa20e, 5, 1, 0, true, f.plane_res_num, f.plane_res_den});
    entries.push_back({0xa210, 3, 1, 2, false, 0, 0});  // inches
  }
  if (f.focal35 > 0) entries.push_back({0xa405, 3, 1, f.focal35, false, 0, 0});
  const uint32_t exif_size = static_cast<uint32_t>(2 + entries.size() * 12 + 4);
  uint32_t rational_at = exif_ifd + exif_size;
  w.U16(static_cast<uint32_t>(entries.size()));
  std::vector<std::pair<uint32_t, uint32_t>> rationals;
  for (const Entry& e : entries) {
    w.U16(e.tag), w.U16(e.type), w.U32(e.count);
    if (e.rational) {
      w.U32(rational_at);
      rational_at += 8;
      rationals.push_back({e.num, e.den});
    } else {
      w.U16(e.value), w.U16(0);  // SHORT, left-justified in the value field
    }
  }
  w.U32(0);
  for (const auto& [num, den] : rationals) w.U32(num), w.U32(den);
  return w.bytes;
}

// A JPEG of `width` x `height` with the EXIF block in an APP1 segment right after SOI.
fs::path WriteJpegWithExif(const fs::path& path, int width, int height, const ExifFields& fields) {
  cv::Mat image(height, width, CV_8UC1);
  cv::randu(image, 0, 255);
  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", image, jpeg);
  std::vector<uint8_t> app1 = {'E', 'x', 'i', 'f', 0, 0};
  const std::vector<uint8_t> tiff = MakeExifBlock(fields);
  app1.insert(app1.end(), tiff.begin(), tiff.end());
  const size_t length = app1.size() + 2;
  std::vector<uint8_t> out = {0xff, 0xd8, 0xff, 0xe1, static_cast<uint8_t>(length >> 8), static_cast<uint8_t>(length & 0xff)};
  out.insert(out.end(), app1.begin(), app1.end());
  out.insert(out.end(), jpeg.begin() + 2, jpeg.end());  // skip the encoder's SOI
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
  return path;
}

TEST(Exif, ReadsBodyFocalAnd35mmEquivalentFromAJpeg) {
  const fs::path path = WriteJpegWithExif(ScratchDir("exif_read") / "a.jpg", 64, 48, ExifFields{});
  const std::optional<ExifMetadata> exif = ReadExifMetadata(path);
  ASSERT_TRUE(exif.has_value());
  EXPECT_EQ(exif->make, "Canon");
  EXPECT_EQ(exif->model, "EOS 5D");
  EXPECT_EQ(exif->Body(), "Canon EOS 5D");
  ASSERT_TRUE(exif->focal_mm.has_value());
  EXPECT_DOUBLE_EQ(*exif->focal_mm, 35.0);
  ASSERT_TRUE(exif->focal_35mm.has_value());
  EXPECT_DOUBLE_EQ(*exif->focal_35mm, 50.0);
  EXPECT_FALSE(exif->focal_plane_x_res_mm.has_value());
  // The decoder still reads the image behind the APP1 segment.
  EXPECT_EQ(cv::imread(path.string(), cv::IMREAD_GRAYSCALE).cols, 64);
}

TEST(Exif, FocalPlaneResolutionIsConvertedToPixelsPerMillimetre) {
  ExifFields fields;
  fields.focal35 = 0;
  fields.focal_num = 71, fields.focal_den = 2;  // 35.5 mm
  fields.plane_res_num = 3000 * 254, fields.plane_res_den = 10 * 36;  // 3000 px over 36 mm, per inch
  const std::optional<ExifMetadata> exif = ReadExifMetadata(WriteJpegWithExif(ScratchDir("exif_plane") / "b.jpg", 60, 40, fields));
  ASSERT_TRUE(exif && exif->focal_plane_x_res_mm);
  EXPECT_NEAR(*exif->focal_plane_x_res_mm, 3000.0 / 36.0, 1e-9);
  EXPECT_DOUBLE_EQ(*exif->focal_mm, 35.5);
  // No PixelXDimension: the resolution refers to this image's long side.
  const FocalPrior focal = FocalFromExif(&*exif, 3000, 2000, {});
  EXPECT_EQ(focal.source, FocalSource::kExifFocalPlane);
  EXPECT_NEAR(focal.focal_px, 35.5 * 3000.0 / 36.0, 1e-6);
}

TEST(Exif, ImagesWithoutExifHaveNone) {
  const fs::path dir = ScratchDir("exif_none");
  cv::Mat image(20, 30, CV_8UC1, cv::Scalar(7));
  cv::imwrite((dir / "plain.png").string(), image);
  cv::imwrite((dir / "plain.jpg").string(), image);
  std::ofstream(dir / "text.jpg") << "not an image";
  EXPECT_FALSE(ReadExifMetadata(dir / "plain.png").has_value());
  EXPECT_FALSE(ReadExifMetadata(dir / "plain.jpg").has_value());
  EXPECT_FALSE(ReadExifMetadata(dir / "text.jpg").has_value());
  EXPECT_FALSE(ReadExifMetadata(dir / "missing.jpg").has_value());
}

TEST(FocalPrior, SourcesInOrderOfPreference) {
  ExifMetadata exif;
  exif.focal_mm = 6.0;
  exif.focal_35mm = 28.0;
  // The 35 mm equivalent keeps the diagonal field of view: 1067 x 800 at 28 mm -> 863 px (the
  // value the books dataset lists in exif_focal.txt).
  FocalPrior focal = FocalFromExif(&exif, 1067, 800, {});
  EXPECT_EQ(focal.source, FocalSource::kExif35mm);
  EXPECT_NEAR(focal.focal_px, 863.0, 0.5);
  EXPECT_TRUE(IsFocalTrusted(focal.source));
  // A sensor width given by the user wins: 6 mm on a 7.2 mm wide sensor, 1067 px wide.
  FocalPriorOptions with_sensor;
  with_sensor.sensor_width_mm = 7.2;
  focal = FocalFromExif(&exif, 1067, 800, with_sensor);
  EXPECT_EQ(focal.source, FocalSource::kExifSensorWidth);
  EXPECT_NEAR(focal.focal_px, 6.0 * 1067 / 7.2, 1e-9);
  // Nothing usable: COLMAP's guess, not trusted.
  focal = FocalFromExif(nullptr, 640, 480, {});
  EXPECT_EQ(focal.source, FocalSource::kDefaultGuess);
  EXPECT_DOUBLE_EQ(focal.focal_px, 768.0);
  EXPECT_FALSE(IsFocalTrusted(focal.source));
  ExifMetadata only_mm;
  only_mm.focal_mm = 6.0;
  EXPECT_EQ(FocalFromExif(&only_mm, 640, 480, {}).source, FocalSource::kDefaultGuess);
  // A tag that gives no real lens falls through to the next source instead of stopping the run.
  ExifMetadata bogus;
  bogus.focal_35mm = 65535.0;  // 65535 mm on 640 px: a 0.03 degree field of view
  EXPECT_EQ(FocalFromExif(&bogus, 640, 480, {}).source, FocalSource::kDefaultGuess);
  bogus.focal_35mm = 0.0;
  EXPECT_EQ(FocalFromExif(&bogus, 640, 480, {}).source, FocalSource::kDefaultGuess);
}

TEST(FocalPrior, NamesRoundTrip) {
  for (FocalSource s : {FocalSource::kUserFocal, FocalSource::kKFile, FocalSource::kExifSensorWidth,
                        FocalSource::kExif35mm, FocalSource::kExifFocalPlane, FocalSource::kDefaultGuess}) {
    EXPECT_EQ(FocalSourceFromName(FocalSourceName(s)), s);
  }
  EXPECT_FALSE(FocalSourceFromName("exif").has_value());
}

}  // namespace
}  // namespace sfm_pruning::testing
