#include <gtest/gtest.h>

#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

SfmData PointsAndCameras() {
  SfmData data;
  Landmark a;
  a.X = {1.0 / 3.0, -2.5, 1e-12};
  a.color = {10, 20, 30};
  Landmark b;
  b.X = {100.25, 7.0, -3.0};
  data.structure[0] = a;
  data.structure[1] = b;
  data.poses[0] = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(4, 5, 6));
  return data;
}

TEST(Ply, BinaryAndAsciiRoundTrip) {
  const auto dir = testing::ScratchDir("ply_roundtrip");
  for (bool binary : {true, false}) {
    const auto path = dir / (binary ? "binary.ply" : "ascii.ply");
    PlyWriteOptions options;
    options.binary = binary;
    WritePly(PointsAndCameras(), path, options);
    const SfmData back = ReadPlyPoints(path);
    ASSERT_EQ(back.structure.size(), 3u);  // two points and one camera centre
    EXPECT_EQ(back.structure.at(0).X, PointsAndCameras().structure.at(0).X);
    EXPECT_EQ(back.structure.at(0).color, (std::array<uint8_t, 3>{10, 20, 30}));
    EXPECT_EQ(back.structure.at(2).X, Eigen::Vector3d(4, 5, 6));
    EXPECT_EQ(back.structure.at(2).color, (std::array<uint8_t, 3>{0, 255, 0}));
  }
}

TEST(Ply, RejectsNonPlyAndTruncatedFiles) {
  const auto dir = testing::ScratchDir("ply_bad");
  WriteFileAtomically(dir / "not.ply", false, [](std::ostream& out) { out << "hello\n"; });
  EXPECT_THROW(ReadPlyPoints(dir / "not.ply"), Error);
  WriteFileAtomically(dir / "short.ply", true, [](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
           "property double z\nend_header\n1234";
  });
  EXPECT_THROW(ReadPlyPoints(dir / "short.ply"), Error);
  EXPECT_THROW(ReadPlyPoints(dir / "missing.ply"), Error);
}

TEST(Ply, SixteenBitColoursAreScaledToBytes) {
  const auto dir = testing::ScratchDir("ply_colour16");
  WriteFileAtomically(dir / "colour16.ply", false, [&](std::ostream& out) {
    out << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
           "property ushort red\nproperty ushort green\nproperty ushort blue\nend_header\n1 2 3 65535 0 32896\n";
  });
  EXPECT_EQ(ReadPlyPoints(dir / "colour16.ply").structure.at(0).color, (std::array<uint8_t, 3>{255, 0, 128}));
}

// Found by fuzz_ply: an ASCII colour outside a byte's range was converted to uint8_t (undefined).
TEST(Ply, RejectsColoursOutsideAByte) {
  const auto dir = testing::ScratchDir("ply_colour");
  for (const char* colour : {"12882 0 0", "0 -1 0", "0 0 255.5"}) {
    SCOPED_TRACE(colour);
    WriteFileAtomically(dir / "colour.ply", false, [&](std::ostream& out) {
      out << "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\nproperty double z\n"
             "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n1 2 3 "
          << colour << "\n";
    });
    try {
      ReadPlyPoints(dir / "colour.ply");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("vertex 0: colour value"), std::string::npos) << e.what();
    }
  }
}

TEST(AtomicFile, FailedWriteLeavesNoFileBehind) {
  const auto dir = testing::ScratchDir("atomic");
  const auto path = dir / "out.txt";
  WriteFileAtomically(path, false, [](std::ostream& out) { out << "first"; });
  EXPECT_THROW(WriteFileAtomically(path, false,
                                   [](std::ostream& out) {
                                     out << "partial";
                                     throw Error("simulated failure");
                                   }),
               Error);
  EXPECT_EQ(ReadFileToString(path), "first");  // the old content survives
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);  // no temporary left behind
}

}  // namespace
}  // namespace sfm_pruning
