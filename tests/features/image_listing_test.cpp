// prunesfm init's library part: listing, decoding failures (skipped with a reason, never fatal),
// camera grouping, focal sources, K files.
#include <gtest/gtest.h>

#include <fstream>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "sfm_pruning/features/image_decoding.hpp"
#include "sfm_pruning/features/image_listing.hpp"
#include "sfm_pruning/io/k_file.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

void WriteImage(const fs::path& path, int width, int height) {
  cv::Mat image(height, width, CV_8UC3);
  cv::randu(image, 0, 255);
  ASSERT_TRUE(cv::imwrite(path.string(), image));
}

// a.png 64x48, b.jpg 64x48, c.PNG 32x40, broken.jpg (JPEG header, then garbage), empty.png,
// notes.txt (not an image).
fs::path MixedFolder(const std::string& name) {
  const fs::path dir = ScratchDir(name);
  WriteImage(dir / "a.png", 64, 48);
  WriteImage(dir / "b.jpg", 64, 48);
  WriteImage(dir / "c.PNG", 32, 40);
  std::ofstream(dir / "broken.jpg", std::ios::binary) << "\xff\xd8\xff\xe0 this is not a JPEG body";
  std::ofstream(dir / "empty.png", std::ios::binary);
  std::ofstream(dir / "notes.txt") << "hello";
  return dir;
}

TEST(ImageListing, ListsImageFilesByNameAnyCase) {
  const fs::path dir = MixedFolder("listing_files");
  EXPECT_EQ(ListImageFiles(dir), (std::vector<std::string>{"a.png", "b.jpg", "broken.jpg", "c.PNG", "empty.png"}));
}

TEST(ImageListing, UndecodableImagesAreSkippedWithAReason) {
  const fs::path dir = MixedFolder("listing_skip");
  const ImageListing listing = ListImages(dir, {});
  ASSERT_EQ(listing.scene.views.size(), 3u);
  EXPECT_EQ(listing.scene.views.at(0).filename, "a.png");
  EXPECT_EQ(listing.scene.views.at(1).filename, "b.jpg");
  EXPECT_EQ(listing.scene.views.at(2).filename, "c.PNG");
  EXPECT_EQ(listing.scene.views.at(2).width, 32u);
  EXPECT_EQ(listing.scene.views.at(2).height, 40u);
  ASSERT_EQ(listing.skipped.size(), 2u);
  EXPECT_EQ(listing.skipped[0].filename, "broken.jpg");
  EXPECT_EQ(listing.skipped[0].reason, "does not decode (a JPEG cut short: no end-of-image marker)");
  EXPECT_EQ(listing.skipped[1].filename, "empty.png");
  EXPECT_EQ(listing.skipped[1].reason, "empty file");
}

// libjpeg decodes a JPEG cut short into a picture with grey rows and only warns on stderr, libpng
// prints an error of its own; such files are skipped with one reason, while bytes after the end of
// the image (camera trailers) are allowed.
TEST(ImageListing, TruncatedJpegsAndPngsAreSkippedTrailersAllowed) {
  const fs::path dir = ScratchDir("listing_truncated_jpeg");
  WriteImage(dir / "whole.jpg", 256, 192);
  WriteImage(dir / "whole.png", 256, 192);
  const std::string jpeg = ReadFileToString(dir / "whole.jpg");
  const std::string png = ReadFileToString(dir / "whole.png");
  std::ofstream(dir / "cut.jpg", std::ios::binary) << jpeg.substr(0, jpeg.size() / 2);
  std::ofstream(dir / "cut.png", std::ios::binary) << png.substr(0, png.size() / 2);
  std::ofstream(dir / "trailer.jpg", std::ios::binary) << jpeg << "TRAILER\xff\xd8 appended data";
  const ImageListing listing = ListImages(dir, {});
  ASSERT_EQ(listing.scene.views.size(), 3u);
  EXPECT_EQ(listing.scene.views.at(0).filename, "trailer.jpg");
  EXPECT_EQ(listing.scene.views.at(1).filename, "whole.jpg");
  EXPECT_EQ(listing.scene.views.at(2).filename, "whole.png");
  ASSERT_EQ(listing.skipped.size(), 2u);
  EXPECT_EQ(listing.skipped[0].filename, "cut.jpg");
  EXPECT_EQ(listing.skipped[0].reason, "does not decode (a JPEG cut short: no end-of-image marker)");
  EXPECT_EQ(listing.skipped[1].filename, "cut.png");
  EXPECT_EQ(listing.skipped[1].reason, "does not decode (a PNG cut short: no IEND chunk)");
}

TEST(ImageListing, GroupsCamerasBySizeAndGuessesTheFocal) {
  const fs::path dir = MixedFolder("listing_groups");
  const ImageListing listing = ListImages(dir, {});
  // a and b share a size (and no EXIF body): one camera; c has its own.
  ASSERT_EQ(listing.scene.intrinsics.size(), 2u);
  EXPECT_EQ(listing.scene.views.at(0).id_intrinsic, listing.scene.views.at(1).id_intrinsic);
  EXPECT_NE(listing.scene.views.at(0).id_intrinsic, listing.scene.views.at(2).id_intrinsic);
  const CameraIntrinsics& camera = listing.scene.intrinsics.at(listing.scene.views.at(0).id_intrinsic);
  EXPECT_EQ(camera.model(), CameraModel::kPinholeRadialK1);
  EXPECT_DOUBLE_EQ(camera.FocalLength(), 1.2 * 64);
  EXPECT_DOUBLE_EQ(camera.PrincipalPoint().x(), 31.5);
  EXPECT_DOUBLE_EQ(camera.PrincipalPoint().y(), 23.5);
  EXPECT_EQ(listing.cameras.at(0).focal_source, FocalSource::kDefaultGuess);
  EXPECT_EQ(listing.cameras.at(0).num_views, 2u);

  ImageListingOptions per_image;
  per_image.grouping = CameraGrouping::kPerImage;
  EXPECT_EQ(ListImages(dir, per_image).scene.intrinsics.size(), 3u);
}

TEST(ImageListing, UserFocalAndKFileAreTrusted) {
  const fs::path dir = MixedFolder("listing_focal");
  ImageListingOptions options;
  options.focal_px = 100.0;
  ImageListing listing = ListImages(dir, options);
  EXPECT_DOUBLE_EQ(listing.scene.intrinsics.at(0).FocalLength(), 100.0);
  EXPECT_EQ(listing.cameras.at(0).focal_source, FocalSource::kUserFocal);

  const fs::path k_file = dir / "K.txt";
  std::ofstream(k_file) << "2759.48 0 1520.69\n0 2764.16 1006.81\n0 0 1\n";
  options = {};
  options.K = ReadKFile(k_file);
  listing = ListImages(dir, options);
  const CameraIntrinsics& camera = listing.scene.intrinsics.at(0);
  EXPECT_EQ(camera.model(), CameraModel::kPinholeFxFy);  // fx != fy is kept exactly
  EXPECT_DOUBLE_EQ(camera.FocalX(), 2759.48);
  EXPECT_DOUBLE_EQ(camera.FocalY(), 2764.16);
  EXPECT_DOUBLE_EQ(camera.PrincipalPoint().x(), 1520.69);
  EXPECT_EQ(listing.cameras.at(0).focal_source, FocalSource::kKFile);
  EXPECT_TRUE(IsFocalTrusted(listing.cameras.at(0).focal_source));
}

TEST(ImageListing, FolderProblemsAreOneLineErrors) {
  const fs::path dir = ScratchDir("listing_errors");
  EXPECT_THROW(ListImages(dir / "missing", {}), Error);
  try {
    ListImages(dir, {});
    FAIL() << "an empty folder must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no image files"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "x.jpg") << "garbage";
  try {
    ListImages(dir, {});
    FAIL() << "a folder where nothing decodes must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x.jpg: does not decode"), std::string::npos) << e.what();
  }
}

TEST(KFile, RejectsWhatIsNotACameraMatrix) {
  const fs::path dir = ScratchDir("k_file_errors");
  std::ofstream(dir / "short.txt") << "1 0 2\n0 1 3\n";
  std::ofstream(dir / "word.txt") << "1 0 2\n0 one 3\n0 0 1\n";
  std::ofstream(dir / "bad.txt") << "1 0 2\n0 1 3\n1 0 1\n";
  for (const char* name : {"short.txt", "word.txt", "bad.txt", "missing.txt"}) {
    try {
      ReadKFile(dir / name);
      FAIL() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sfm_pruning::testing
