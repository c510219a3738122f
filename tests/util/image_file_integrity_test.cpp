#include "sfm_pruning/util/image_file_integrity.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sfm_pruning::testing {
namespace {

// A PNG's chunk: 4-byte big-endian length, type, data, a CRC the check does not verify.
std::string Chunk(const std::string& type, const std::string& data) {
  std::string chunk;
  for (int shift : {24, 16, 8, 0}) chunk += static_cast<char>((data.size() >> shift) & 0xFF);
  return chunk + type + data + "CRC!";
}

const std::string kPngSignature("\x89PNG\r\n\x1a\n", 8);

// SOI, an APP0 segment holding an EXIF-style thumbnail end marker, SOS with scan data, EOI.
std::string Jpeg() {
  return std::string("\xff\xd8\xff\xe0\x00\x06\xff\xd9\x00\x00", 10) + std::string("\xff\xda\x00\x02", 4) +
         std::string(
             "scan\xff\x00"
             "data\xff\xd0"
             "more",
             16) +
         std::string("\xff\xd9", 2);
}

TEST(ImageFileIntegrity, PngMustReachItsEndChunk) {
  const std::string png =
      kPngSignature + Chunk("IHDR", std::string(13, 'h')) + Chunk("IDAT", "pixels") + Chunk("IEND", "");
  EXPECT_TRUE(PngIsComplete(png));
  EXPECT_EQ(ImageCutShortProblem(png), "");
  EXPECT_TRUE(PngIsComplete(png + "appended"));  // bytes after IEND, as libpng allows
  for (const size_t size : {png.size() / 2, png.size() - 1, kPngSignature.size()}) {
    EXPECT_FALSE(PngIsComplete(png.substr(0, size))) << size;
    EXPECT_EQ(ImageCutShortProblem(png.substr(0, size)), "a PNG cut short: no IEND chunk") << size;
  }
  // A chunk length past the end of the file (a corrupt length) never reaches IEND.
  const std::string huge_length =
      kPngSignature + std::string("\xff\xff\xff\xf0", 4) + "IDAT" + Chunk("IEND", "");
  EXPECT_FALSE(PngIsComplete(huge_length));
}

TEST(ImageFileIntegrity, JpegMustEndItsScan) {
  const std::string jpeg = Jpeg();
  EXPECT_TRUE(JpegIsComplete(jpeg));
  EXPECT_EQ(ImageCutShortProblem(jpeg), "");
  EXPECT_TRUE(JpegIsComplete(jpeg + "TRAILER"));
  // Cut inside the scan: the thumbnail's end marker in APP0 does not count.
  EXPECT_FALSE(JpegIsComplete(jpeg.substr(0, jpeg.size() - 2)));
  EXPECT_EQ(ImageCutShortProblem(jpeg.substr(0, 20)), "a JPEG cut short: no end-of-image marker");
}

TEST(ImageFileIntegrity, OtherFormatsAreLeftToTheirCodecs) {
  EXPECT_EQ(ImageCutShortProblem(""), "");
  EXPECT_EQ(ImageCutShortProblem("II*\0 a TIFF cut short"), "");
  EXPECT_EQ(ImageCutShortProblem("not an image at all"), "");
}

}  // namespace
}  // namespace sfm_pruning::testing
