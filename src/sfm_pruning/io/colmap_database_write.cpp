// Writing COLMAP databases: a new one in COLMAP 3.8's schema, and a copy with a subset of the
// two-view geometries. Both are built in memory and written with WriteFileAtomically, so no
// reader ever sees a half-written database.
#include <Eigen/Geometry>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/io/colmap_camera.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/colmap_database_blobs.hpp"
#include "sfm_pruning/io/colmap_sqlite.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
using colmap_blobs::EncodeArray;
using colmap_sqlite::Connection;
using colmap_sqlite::Statement;

namespace {

constexpr IndexT kMaxColmapImageId = 2147483646;  // image ids must stay below COLMAP's pair multiplier

// COLMAP 3.8 reads rows by column position, so the columns follow its order exactly.
constexpr const char* kSchema38 = R"sql(
CREATE TABLE cameras (camera_id INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, model INTEGER NOT NULL,
  width INTEGER NOT NULL, height INTEGER NOT NULL, params BLOB, prior_focal_length INTEGER NOT NULL);
CREATE TABLE images (image_id INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, name TEXT NOT NULL UNIQUE,
  camera_id INTEGER NOT NULL, prior_qw REAL, prior_qx REAL, prior_qy REAL, prior_qz REAL,
  prior_tx REAL, prior_ty REAL, prior_tz REAL,
  CONSTRAINT image_id_check CHECK(image_id >= 0 AND image_id < 2147483647),
  FOREIGN KEY(camera_id) REFERENCES cameras(camera_id));
CREATE UNIQUE INDEX index_name ON images(name);
CREATE TABLE keypoints (image_id INTEGER PRIMARY KEY NOT NULL, rows INTEGER NOT NULL, cols INTEGER NOT NULL,
  data BLOB, FOREIGN KEY(image_id) REFERENCES images(image_id) ON DELETE CASCADE);
CREATE TABLE descriptors (image_id INTEGER PRIMARY KEY NOT NULL, rows INTEGER NOT NULL, cols INTEGER NOT NULL,
  data BLOB, FOREIGN KEY(image_id) REFERENCES images(image_id) ON DELETE CASCADE);
CREATE TABLE matches (pair_id INTEGER PRIMARY KEY NOT NULL, rows INTEGER NOT NULL, cols INTEGER NOT NULL,
  data BLOB);
CREATE TABLE two_view_geometries (pair_id INTEGER PRIMARY KEY NOT NULL, rows INTEGER NOT NULL,
  cols INTEGER NOT NULL, data BLOB, config INTEGER NOT NULL, F BLOB, E BLOB, H BLOB, qvec BLOB, tvec BLOB);
)sql";

void BindBlob(Statement& statement, int index, const std::string& bytes) {
  statement.BindBlob(index, bytes.data(), bytes.size());
}

void WriteCamerasAndImages(const SfmData& data, const std::set<IndexT>& guessed_focal, const std::string& source,
                           Connection& db) {
  Statement camera_row = db.Prepare(
      "INSERT INTO cameras (camera_id, model, width, height, params, prior_focal_length) VALUES (?, ?, ?, ?, "
      "?, ?)");
  for (const auto& [intrinsic_id, intrinsics] : data.intrinsics) {
    ColmapCamera camera;
    try {
      camera = ToColmapCamera(intrinsics);
    } catch (const Error& e) {
      throw FileError(source, "intrinsic " + std::to_string(intrinsic_id) + ": " + e.what());
    }
    camera_row.BindInt64(1, intrinsic_id);
    camera_row.BindInt64(2, camera.model_id);
    camera_row.BindInt64(3, static_cast<int64_t>(camera.width));
    camera_row.BindInt64(4, static_cast<int64_t>(camera.height));
    BindBlob(camera_row, 5, EncodeArray(camera.params));
    camera_row.BindInt64(6, guessed_focal.count(intrinsic_id) > 0 ? 0 : 1);
    camera_row.Run();
  }
  Statement image_row = db.Prepare("INSERT INTO images (image_id, name, camera_id) VALUES (?, ?, ?)");
  for (const auto& [view_id, view] : data.views) {
    if (view_id > kMaxColmapImageId) {
      throw FileError(source, "view id " + std::to_string(view_id) + " is too large for a COLMAP image id");
    }
    if (data.intrinsics.count(view.id_intrinsic) == 0) {
      throw FileError(source, "view " + std::to_string(view_id) + " has no intrinsic; COLMAP needs a camera");
    }
    image_row.BindInt64(1, view_id);
    image_row.BindText(2, view.RelativeImagePath());
    image_row.BindInt64(3, view.id_intrinsic);
    image_row.Run();
  }
}

void WriteFeatures(const ColmapDatabase& database, const std::string& source, Connection& db) {
  Statement keypoint_row =
      db.Prepare("INSERT INTO keypoints (image_id, rows, cols, data) VALUES (?, ?, 4, ?)");
  Statement descriptor_row =
      db.Prepare("INSERT INTO descriptors (image_id, rows, cols, data) VALUES (?, ?, 128, ?)");
  for (const auto& [view_id, features] : database.features) {
    if (database.sfm_data.views.count(view_id) == 0) {
      throw FileError(source, "features given for missing view " + std::to_string(view_id));
    }
    std::vector<float> values;
    values.reserve(4 * features.size());
    for (const Keypoint& keypoint : features.keypoints) {
      values.insert(values.end(), {keypoint.x + static_cast<float>(kColmapPixelOffset),
                                   keypoint.y + static_cast<float>(kColmapPixelOffset), keypoint.scale,
                                   keypoint.orientation});
    }
    keypoint_row.BindInt64(1, view_id);
    keypoint_row.BindInt64(2, static_cast<int64_t>(features.size()));
    BindBlob(keypoint_row, 3, EncodeArray(values));
    keypoint_row.Run();
    if (features.descriptors.empty()) continue;
    if (features.descriptors.size() != features.size()) {
      throw FileError(source, "view " + std::to_string(view_id) + " has " +
                                  std::to_string(features.descriptors.size()) + " descriptors for " +
                                  std::to_string(features.size()) + " keypoints");
    }
    descriptor_row.BindInt64(1, view_id);
    descriptor_row.BindInt64(2, static_cast<int64_t>(features.size()));
    BindBlob(descriptor_row, 3, EncodeArray(features.descriptors));
    descriptor_row.Run();
  }
}

std::string EncodeMatches(const std::vector<FeatureMatch>& matches) {
  std::vector<uint32_t> values;
  values.reserve(2 * matches.size());
  for (const FeatureMatch& match : matches) values.insert(values.end(), {match.i, match.j});
  return EncodeArray(values);
}

void CheckPair(const ColmapDatabase& database, const ViewPair& pair, const std::string& source) {
  if (pair.first >= pair.second || database.sfm_data.views.count(pair.first) == 0 ||
      database.sfm_data.views.count(pair.second) == 0) {
    throw FileError(source, "pair " + std::to_string(pair.first) + "-" + std::to_string(pair.second) +
                                " is not an ordered pair of existing views");
  }
}

// Inserts a two_view_geometries row per pair (COLMAP 3.8's columns; a database of an older schema
// without qvec and tvec gets the others).
void InsertTwoViewGeometries(const std::map<ViewPair, ColmapTwoViewGeometry>& verified, Connection& db) {
  const bool has_pose = db.HasColumn("two_view_geometries", "qvec") && db.HasColumn("two_view_geometries", "tvec");
  Statement geometry_row =
      db.Prepare(has_pose ? "INSERT INTO two_view_geometries (pair_id, rows, cols, data, config, F, E, H, qvec, tvec) "
                            "VALUES (?, ?, 2, ?, ?, ?, ?, ?, ?, ?)"
                          : "INSERT INTO two_view_geometries (pair_id, rows, cols, data, config, F, E, H) "
                            "VALUES (?, ?, 2, ?, ?, ?, ?, ?)");
  for (const auto& [pair, geometry] : verified) {
    geometry_row.BindInt64(1, static_cast<int64_t>(ColmapPairId(pair.first, pair.second)));
    geometry_row.BindInt64(2, static_cast<int64_t>(geometry.inliers.size()));
    BindBlob(geometry_row, 3, EncodeMatches(geometry.inliers));
    geometry_row.BindInt64(4, geometry.config);
    BindBlob(geometry_row, 5, colmap_blobs::EncodeMatrix3(geometry.F));
    BindBlob(geometry_row, 6, colmap_blobs::EncodeMatrix3(geometry.E));
    BindBlob(geometry_row, 7, colmap_blobs::EncodeMatrix3(geometry.H));
    if (has_pose) {
      // Like COLMAP 3.8, an absent relative pose is stored as zeros.
      std::vector<double> qvec(4, 0.0), tvec(3, 0.0);
      if (geometry.relative_pose) {
        const Eigen::Quaterniond q(geometry.relative_pose->rotation);
        const Eigen::Vector3d& t = geometry.relative_pose->translation;
        qvec = {q.w(), q.x(), q.y(), q.z()};
        tvec = {t.x(), t.y(), t.z()};
      }
      BindBlob(geometry_row, 8, EncodeArray(qvec));
      BindBlob(geometry_row, 9, EncodeArray(tvec));
    }
    geometry_row.Run();
  }
}

void WriteMatches(const ColmapDatabase& database, const std::string& source, Connection& db) {
  Statement match_row = db.Prepare("INSERT INTO matches (pair_id, rows, cols, data) VALUES (?, ?, 2, ?)");
  for (const auto& [pair, matches] : database.putative) {
    CheckPair(database, pair, source);
    match_row.BindInt64(1, static_cast<int64_t>(ColmapPairId(pair.first, pair.second)));
    match_row.BindInt64(2, static_cast<int64_t>(matches.size()));
    BindBlob(match_row, 3, EncodeMatches(matches));
    match_row.Run();
  }
  for (const auto& [pair, geometry] : database.verified) CheckPair(database, pair, source);
  InsertTwoViewGeometries(database.verified, db);
}

void WriteBytes(const fs::path& path, const std::string& bytes) {
  WriteFileAtomically(path, true, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace

void WriteColmapDatabase(const ColmapDatabase& database, const fs::path& path) {
  const std::string source = path.string();
  Connection db = Connection::OpenInMemory(source);
  db.Execute("BEGIN");
  // sqlite3_prepare handles one statement at a time, so the schema is split at semicolons.
  const std::string schema = kSchema38;
  for (size_t start = 0, end = schema.find(';'); end != std::string::npos;
       start = end + 1, end = schema.find(';', start)) {
    db.Execute(schema.substr(start, end - start));
  }
  WriteCamerasAndImages(database.sfm_data, database.intrinsics_with_guessed_focal, source, db);
  WriteFeatures(database, source, db);
  WriteMatches(database, source, db);
  db.Execute("COMMIT");
  WriteBytes(path, db.Serialize());
}

namespace {

// Rewrites the inlier blob of two_view_geometries row `pair_id` without the matches of `drop`.
void DropInliers(Connection& db, int64_t pair_id, const std::vector<FeatureMatch>& drop) {
  std::set<std::pair<uint32_t, uint32_t>> dropped;
  for (const FeatureMatch& match : drop) dropped.emplace(match.i, match.j);
  std::string data;
  int64_t rows = 0, cols = 0;
  {
    Statement row = db.Prepare("SELECT rows, cols, data FROM two_view_geometries WHERE pair_id = ?");
    row.BindInt64(1, pair_id);
    if (!row.Step()) return;
    rows = row.ColumnInt64(0);
    cols = row.ColumnInt64(1);
    data = row.ColumnBlob(2);
  }
  if (cols != 2 || data.size() != static_cast<size_t>(rows) * 2 * sizeof(uint32_t)) {
    throw FileError(db.source(), "two_view_geometries row " + std::to_string(pair_id) + " is not rows x 2 uint32");
  }
  std::vector<uint32_t> values(2 * static_cast<size_t>(rows));
  std::memcpy(values.data(), data.data(), data.size());
  std::vector<uint32_t> kept;
  for (size_t k = 0; k + 1 < values.size(); k += 2) {
    if (dropped.count({values[k], values[k + 1]}) == 0) kept.insert(kept.end(), {values[k], values[k + 1]});
  }
  Statement update = db.Prepare("UPDATE two_view_geometries SET rows = ?, data = ? WHERE pair_id = ?");
  update.BindInt64(1, static_cast<int64_t>(kept.size() / 2));
  static const uint32_t kNoInlier = 0;  // a zero-length blob, not NULL, when every inlier goes
  update.BindBlob(2, kept.empty() ? &kNoInlier : kept.data(), kept.size() * sizeof(uint32_t));
  update.BindInt64(3, pair_id);
  update.Run();
}

}  // namespace

void CopyColmapDatabaseKeepingPairs(const fs::path& input, const fs::path& output, const std::set<ViewPair>& keep,
                                    const std::map<ViewPair, std::vector<FeatureMatch>>& drop) {
  Connection db = Connection::InMemoryCopyOf(input.string());
  colmap_sqlite::RequireColmapTables(db);
  std::vector<int64_t> dropped;
  {
    Statement rows = db.Prepare("SELECT pair_id FROM two_view_geometries ORDER BY pair_id");
    while (rows.Step()) {
      const int64_t pair_id = rows.ColumnInt64(0);
      if (keep.count(ColmapPairFromId(static_cast<uint64_t>(pair_id))) == 0) dropped.push_back(pair_id);
    }
  }
  db.Execute("BEGIN");
  Statement remove = db.Prepare("DELETE FROM two_view_geometries WHERE pair_id = ?");
  for (int64_t pair_id : dropped) {
    remove.BindInt64(1, pair_id);
    remove.Run();
  }
  for (const auto& [pair, matches] : drop) {
    if (keep.count(pair) != 0 && !matches.empty()) {
      DropInliers(db, static_cast<int64_t>(ColmapPairId(pair.first, pair.second)), matches);
    }
  }
  db.Execute("COMMIT");
  WriteBytes(output, db.Serialize());
}

void CopyColmapDatabaseWithGeometries(const fs::path& input, const fs::path& output,
                                      const std::map<ViewPair, ColmapTwoViewGeometry>& verified) {
  Connection db = Connection::InMemoryCopyOf(input.string());
  colmap_sqlite::RequireColmapTables(db);
  db.Execute("BEGIN");
  db.Execute("DELETE FROM two_view_geometries");
  InsertTwoViewGeometries(verified, db);
  db.Execute("COMMIT");
  WriteBytes(output, db.Serialize());
}

}  // namespace sfm_pruning
