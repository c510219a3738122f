// `prunesfm run IMAGES OUT` on folders that cannot give a reconstruction: the error names the image
// folder and says what is missing, not a match file the run wrote itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

void WriteNoiseJpeg(const fs::path& path) {
  cv::Mat image(96, 128, CV_8UC3);
  cv::randu(image, 0, 255);
  ASSERT_TRUE(cv::imwrite(path.string(), image));
}

void ExpectTooFewImages(const fs::path& images, const fs::path& out) {
  const CommandResult result = RunPrunesfm({"run", images.string(), out.string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  const std::string last_line = result.err.substr(result.err.rfind("prunesfm: error:"));
  EXPECT_EQ(CountLines(last_line), 1) << result.err;
  EXPECT_NE(last_line.find(images.string() + ": only 1 image decodes; a reconstruction needs at least two"),
            std::string::npos)
      << result.err;
  EXPECT_EQ(last_line.find("matches"), std::string::npos) << result.err;
}

TEST(CliTooFewImages, OneImage) {
  const fs::path scratch = ScratchDir("cli_one_image");
  fs::create_directories(scratch / "images");
  WriteNoiseJpeg(scratch / "images" / "a.jpg");
  ExpectTooFewImages(scratch / "images", scratch / "out");
}

TEST(CliTooFewImages, OneGoodImageAndATruncatedOne) {
  const fs::path scratch = ScratchDir("cli_truncated_image");
  fs::create_directories(scratch / "images");
  WriteNoiseJpeg(scratch / "images" / "a.jpg");
  std::ifstream in(scratch / "images" / "a.jpg", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(scratch / "images" / "b.jpg", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  ExpectTooFewImages(scratch / "images", scratch / "out");
}

}  // namespace
}  // namespace sfm_pruning::testing
