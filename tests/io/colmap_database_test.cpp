// COLMAP databases: the real temple databases of COLMAP 3.8 and 4.1.1, write/read round trips,
// the pair filter and error handling.
#include "sfm_pruning/io/colmap_database.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <string>

#include "sfm_pruning/io/colmap_camera.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

struct RealDatabase {
  const char* folder;
  size_t putative_pairs;
  size_t putative_matches;
  size_t verified_pairs;
  size_t inliers;
};

size_t TotalKeypoints(const ColmapDatabase& db) {
  size_t total = 0;
  for (const auto& [id, features] : db.features) total += features.size();
  return total;
}

template <typename Map, typename Count>
size_t Sum(const Map& map, Count count) {
  size_t total = 0;
  for (const auto& [pair, value] : map) total += count(value);
  return total;
}

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Median over inliers of |x2^T M x1| / (|M x1|_xy) (distance to the epipolar line), with x1, x2
// homogeneous points obtained by `to_point`.
template <typename ToPoint>
double MedianEpipolarDistance(const ColmapDatabase& db, const ViewPair& pair, const Eigen::Matrix3d& M,
                              ToPoint to_point) {
  std::vector<double> distances;
  for (const FeatureMatch& match : db.verified.at(pair).inliers) {
    const Eigen::Vector3d x1 = to_point(pair.first, match.i);
    const Eigen::Vector3d x2 = to_point(pair.second, match.j);
    const Eigen::Vector3d line = M * x1;
    distances.push_back(std::abs(x2.dot(line)) / line.head<2>().norm());
  }
  return Median(distances);
}

TEST(ColmapDatabase, ReadsRealDatabasesOfBothSchemas) {
  for (const RealDatabase& real :
       {RealDatabase{"colmap-3.8", 46, 7893, 35, 7510}, RealDatabase{"colmap-4.1.1", 43, 7723, 36, 7436}}) {
    SCOPED_TRACE(real.folder);
    PRUNESFM_REQUIRE_SHARED(std::string("formats/colmap/") + real.folder + "/database.db", path);
    const ColmapDatabase db = ReadColmapDatabase(path);
    EXPECT_EQ(db.sfm_data.views.size(), 16u);
    EXPECT_TRUE(db.sfm_data.poses.empty());
    EXPECT_EQ(db.features.size(), 16u);
    EXPECT_EQ(TotalKeypoints(db), 23852u);
    for (const auto& [id, features] : db.features) EXPECT_EQ(features.descriptors.size(), features.size());
    EXPECT_EQ(db.putative.size(), real.putative_pairs);
    EXPECT_EQ(Sum(db.putative, [](const auto& m) { return m.size(); }), real.putative_matches);
    EXPECT_EQ(db.verified.size(), real.verified_pairs);
    EXPECT_EQ(Sum(db.verified, [](const ColmapTwoViewGeometry& g) { return g.inliers.size(); }), real.inliers);

    ASSERT_EQ(db.sfm_data.intrinsics.size(), 1u);
    const CameraIntrinsics& camera = db.sfm_data.intrinsics.at(1);
    EXPECT_EQ(camera.model(), CameraModel::kPinholeFxFy);
    EXPECT_EQ(camera.params(), (std::vector<double>{1520.4, 1525.9, 302.32 - 0.5, 246.87 - 0.5}));
    EXPECT_EQ(db.sfm_data.views.at(1).width, 640u);
    EXPECT_EQ(db.sfm_data.views.at(1).filename.substr(0, 8), "templeSR");

    // E and F (row-major blobs) relate the first image of the pair (smaller id) to the second:
    // inliers lie on the epipolar lines. Pixels for F are in COLMAP's convention.
    const auto normalized = [&](IndexT view, IndexT feature) {
      return camera.PixelToNormalized(db.features.at(view).Position(feature)).homogeneous().eval();
    };
    const auto colmap_pixel = [&](IndexT view, IndexT feature) {
      return ToColmapPixel(db.features.at(view).Position(feature)).homogeneous().eval();
    };
    // Per calibrated pair, median distances in pixels; compared as medians over the pairs since
    // a few near-degenerate pairs fit both directions loosely.
    std::vector<double> with_e, with_f, with_f_transposed;
    for (const auto& [pair, geometry] : db.verified) {
      if (geometry.config != static_cast<int>(ColmapTwoViewConfig::kCalibrated)) continue;
      EXPECT_FALSE(geometry.relative_pose.has_value());  // not computed by the default matcher
      with_e.push_back(MedianEpipolarDistance(db, pair, geometry.E, normalized) * camera.FocalLength());
      with_f.push_back(MedianEpipolarDistance(db, pair, geometry.F, colmap_pixel));
      with_f_transposed.push_back(MedianEpipolarDistance(db, pair, geometry.F.transpose(), colmap_pixel));
      EXPECT_LT(with_e.back(), 2.0);  // COLMAP's RANSAC threshold is 4 px
    }
    ASSERT_GT(with_e.size(), 30u);
    EXPECT_LT(Median(with_e), 0.4);
    EXPECT_LT(Median(with_f), 0.4);
    // The opposite direction does not fit: the test can tell the two apart.
    EXPECT_GT(Median(with_f_transposed), 4.0);
  }
}

TEST(ColmapDatabase, WriteReadRoundTripIsExact) {
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-3.8/database.db", path);
  ColmapDatabase original = ReadColmapDatabase(path);
  // Give one pair a relative pose to carry.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  original.verified.begin()->second.relative_pose = RelativePose(R, Eigen::Vector3d(-0.6, 0, 0.8));
  const fs::path out = testing::ScratchDir("colmap_database_roundtrip") / "database.db";
  WriteColmapDatabase(original, out);
  const ColmapDatabase back = ReadColmapDatabase(out);
  EXPECT_EQ(back.sfm_data.views, original.sfm_data.views);
  EXPECT_EQ(back.sfm_data.intrinsics, original.sfm_data.intrinsics);
  ASSERT_EQ(back.features.size(), original.features.size());
  for (const auto& [id, features] : original.features) {
    const FeatureSet& other = back.features.at(id);
    ASSERT_EQ(other.size(), features.size());
    for (size_t k = 0; k < features.size(); ++k) {
      EXPECT_EQ(other.keypoints[k].x, features.keypoints[k].x);
      EXPECT_EQ(other.keypoints[k].y, features.keypoints[k].y);
      EXPECT_EQ(other.keypoints[k].scale, features.keypoints[k].scale);
      EXPECT_EQ(other.keypoints[k].orientation, features.keypoints[k].orientation);
    }
    EXPECT_EQ(other.descriptors, features.descriptors);
  }
  EXPECT_EQ(back.putative, original.putative);
  ASSERT_EQ(back.verified.size(), original.verified.size());
  for (const auto& [pair, geometry] : original.verified) {
    const ColmapTwoViewGeometry& other = back.verified.at(pair);
    EXPECT_EQ(other.inliers, geometry.inliers);
    EXPECT_EQ(other.config, geometry.config);
    EXPECT_EQ(other.F, geometry.F);
    EXPECT_EQ(other.E, geometry.E);
    EXPECT_EQ(other.H, geometry.H);
    ASSERT_EQ(other.relative_pose.has_value(), geometry.relative_pose.has_value());
    if (geometry.relative_pose) {
      EXPECT_LT((other.relative_pose->rotation - R).norm(), 1e-15);
      EXPECT_EQ(other.relative_pose->translation, Eigen::Vector3d(-0.6, 0, 0.8));
    }
  }
}

TEST(ColmapDatabase, CopyKeepsOnlyTheListedPairs) {
  for (const char* folder : {"colmap-3.8", "colmap-4.1.1"}) {
    SCOPED_TRACE(folder);
    PRUNESFM_REQUIRE_SHARED(std::string("formats/colmap/") + folder + "/database.db", path);
    const ColmapDatabase original = ReadColmapDatabase(path);
    std::set<ViewPair> keep;
    for (const auto& [pair, geometry] : original.verified) {
      if (keep.size() % 2 == 0 || pair.first == 1) keep.insert(pair);
      if (keep.size() == 10) break;
    }
    keep.insert({14, 15});  // a pair without a geometry changes nothing
    const fs::path out = testing::ScratchDir(std::string("colmap_database_copy_") + folder) / "pruned.db";
    CopyColmapDatabaseKeepingPairs(path, out, keep);
    const ColmapDatabase pruned = ReadColmapDatabase(out);
    std::set<ViewPair> kept;
    for (const auto& [pair, geometry] : pruned.verified) {
      kept.insert(pair);
      EXPECT_EQ(geometry.inliers, original.verified.at(pair).inliers);
    }
    std::set<ViewPair> expected;
    for (const ViewPair& pair : keep) {
      if (original.verified.count(pair)) expected.insert(pair);
    }
    EXPECT_EQ(kept, expected);
    EXPECT_EQ(pruned.putative, original.putative);
    EXPECT_EQ(pruned.features.size(), original.features.size());
  }
}

void ExpectReadError(const fs::path& path, const std::string& text) {
  try {
    ReadColmapDatabase(path);
    ADD_FAILURE() << "expected an Error mentioning " << text;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(text), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

View MakeView(IndexT id, IndexT intrinsic, const std::string& name) {
  View view;
  view.id_view = id;
  view.id_pose = id;
  view.id_intrinsic = intrinsic;
  view.filename = name;
  return view;
}

// Two images of one camera, three keypoints, one putative match.
ColmapDatabase SmallDatabase() {
  ColmapDatabase small;
  small.sfm_data.intrinsics[1] = CameraIntrinsics::Pinhole(100, 80, 90, 49.5, 39.5);
  small.sfm_data.views[1] = MakeView(1, 1, "a.png");
  small.sfm_data.views[2] = MakeView(2, 1, "b.png");
  small.features[1].keypoints = {{1.f, 2.f, 3.f, 0.5f}, {4.f, 5.f, 1.f, 0.f}};
  small.features[2].keypoints = {{6.f, 7.f, 2.f, 0.25f}};
  small.putative[{1, 2}] = {{1, 0}};
  return small;
}

void ExecuteSql(const fs::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

TEST(ColmapDatabase, RejectsBadFiles) {
  const fs::path dir = testing::ScratchDir("colmap_database_errors");
  ExpectReadError(dir / "missing.db", "file not found");
  std::ofstream(dir / "text.db") << "this is not a database, just text long enough to fill a header......\n";
  ExpectReadError(dir / "text.db", "file is not a database");
  ExecuteSql(dir / "other.db",
             "CREATE TABLE cameras (camera_id INTEGER); CREATE TABLE images (image_id INTEGER);");
  ExpectReadError(dir / "other.db", "not a COLMAP database: table 'keypoints' is missing");

  ColmapDatabase small = SmallDatabase();
  const fs::path path = dir / "small.db";
  WriteColmapDatabase(small, path);
  const ColmapDatabase back = ReadColmapDatabase(path);
  EXPECT_EQ(back.features.at(1).keypoints[1].x, 4.f);
  EXPECT_EQ(back.putative, small.putative);
  EXPECT_EQ(back.sfm_data.views.at(2).width, 100u);

  ExecuteSql(path, "UPDATE keypoints SET rows = 3 WHERE image_id = 1");
  ExpectReadError(path, "keypoints of image 1 blob has 32 bytes, expected 48");
  ExecuteSql(
      path,
      "UPDATE keypoints SET rows = 2 WHERE image_id = 1; UPDATE matches SET data = x'0500000000000000'");
  ExpectReadError(path, "reference a keypoint that does not exist");
  ExecuteSql(path, "UPDATE cameras SET model = 7, params = x'00'");
  ExpectReadError(path, "camera 1 params blob has 1 bytes, expected 40");

  // A view without an intrinsic cannot become a COLMAP image; nothing is written.
  small.sfm_data.views[3] = MakeView(3, kUndefinedIndex, "c.png");
  EXPECT_THROW(WriteColmapDatabase(small, dir / "bad.db"), Error);
  EXPECT_FALSE(fs::exists(dir / "bad.db"));
}

// Numbers that no camera, keypoint or pair can have are refused where they are read, with the row
// they are in: a NaN focal would otherwise keep the verification busy for minutes.
TEST(ColmapDatabase, RejectsImpossibleNumbers) {
  const fs::path dir = testing::ScratchDir("colmap_database_numbers");
  ColmapDatabase small = SmallDatabase();
  ColmapTwoViewGeometry geometry;
  geometry.inliers = {{1, 0}};
  geometry.config = 2;
  small.verified[{1, 2}] = geometry;
  const auto fresh = [&](const std::string& name) {
    const fs::path path = dir / name;
    WriteColmapDatabase(small, path);
    EXPECT_NO_THROW(ReadColmapDatabase(path));
    return path;
  };
  // SIMPLE_PINHOLE params f, cx, cy as doubles; 0x7FF8... is NaN, 0x7FF0... infinity.
  const std::string nan = "000000000000F87F", inf = "000000000000F07F", one = "000000000000F03F";
  const std::pair<std::string, std::string> cases[] = {
      {"UPDATE cameras SET model = 0, params = x'" + nan + one + one + "'", "camera 1: a parameter is not a finite number"},
      {"UPDATE cameras SET model = 0, params = x'" + inf + one + one + "'", "camera 1: a parameter is not a finite number"},
      {"UPDATE cameras SET model = 0, params = x'000000000000F0BF" + one + one + "'",
       "camera 1: focal length must be positive"},
      {"UPDATE cameras SET width = -5", "camera 1: image size -5x80 is not a real image's"},
      {"UPDATE cameras SET height = 0", "camera 1: image size 100x0 is not a real image's"},
      {"UPDATE keypoints SET rows = -1 WHERE image_id = 2", "keypoints of image 2: the row count -1 is negative"},
      {"UPDATE keypoints SET data = x'0000C07F000000400000404000000000' WHERE image_id = 2",
       "keypoints of image 2: keypoint 0 is not finite"},
      {"UPDATE matches SET pair_id = 9223372036854775807", "matches: pair_id 9223372036854775807 is not a pair"},
      {"UPDATE two_view_geometries SET rows = -5", "inliers: the row count -5 is negative"},
      {"UPDATE two_view_geometries SET F = x'" + nan + std::string(8 * 16, '0') + "'", "F is not finite"},
  };
  int index = 0;
  for (const auto& [sql, message] : cases) {
    SCOPED_TRACE(sql);
    const fs::path path = fresh("case" + std::to_string(index++) + ".db");
    ExecuteSql(path, sql);
    ExpectReadError(path, message);
  }
}

}  // namespace
}  // namespace sfm_pruning
