// Reading COLMAP's database.db, both the 3.x and the 4.x schema: only columns common to both
// are selected by name, so the extra 4.x tables and the 4.x `type` column of descriptors never
// matter.
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "sfm_pruning/io/colmap_camera.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/colmap_database_blobs.hpp"
#include "sfm_pruning/io/colmap_sqlite.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
using colmap_blobs::DecodeArray;
using colmap_sqlite::Connection;
using colmap_sqlite::Statement;

namespace {

constexpr uint64_t kMaxNumImages = 2147483647;  // COLMAP's pair id multiplier

void ReadCameras(Connection& db, ColmapDatabase* out) {
  // prior_focal_length = 0: COLMAP guessed the focal (no EXIF); a database without the column
  // (not written by COLMAP) has known intrinsics.
  const bool has_prior_flag = db.HasColumn("cameras", "prior_focal_length");
  Statement rows = db.Prepare(std::string("SELECT camera_id, model, width, height, params") +
                              (has_prior_flag ? ", prior_focal_length" : "") + " FROM cameras ORDER BY camera_id");
  while (rows.Step()) {
    const auto camera_id = static_cast<IndexT>(rows.ColumnInt64(0));
    const std::string name = "camera " + std::to_string(camera_id);
    ColmapCamera camera;
    camera.model_id = static_cast<int>(rows.ColumnInt64(1));
    const int64_t width = rows.ColumnInt64(2), height = rows.ColumnInt64(3);
    if (width <= 0 || height <= 0) {
      throw FileError(db.source(), name + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                                       " is not a real image's");
    }
    camera.width = static_cast<uint64_t>(width);
    camera.height = static_cast<uint64_t>(height);
    const std::string blob = rows.ColumnBlob(4);
    const size_t num_params = ColmapCameraNumParams(camera.model_id);
    // Unknown models keep no parameters; FromColmapCamera then names the model in its error.
    if (num_params > 0) {
      camera.params = DecodeArray<double>(blob, num_params, db.source(), name + " params");
    }
    const CameraIntrinsics intrinsics = FromColmapCamera(camera, db.source());
    const std::string problem = IntrinsicsProblem(intrinsics);
    if (!problem.empty()) throw FileError(db.source(), name + ": " + problem);
    out->sfm_data.intrinsics[camera_id] = intrinsics;
    if (has_prior_flag && rows.ColumnInt64(5) == 0) out->intrinsics_with_guessed_focal.insert(camera_id);
  }
}

void ReadImages(Connection& db, ColmapDatabase* out) {
  Statement rows = db.Prepare("SELECT image_id, name, camera_id FROM images ORDER BY image_id");
  while (rows.Step()) {
    View view;
    view.id_view = static_cast<IndexT>(rows.ColumnInt64(0));
    view.id_pose = view.id_view;
    view.id_intrinsic = static_cast<IndexT>(rows.ColumnInt64(2));
    view.filename = rows.ColumnText(1);
    const auto intrinsic = out->sfm_data.intrinsics.find(view.id_intrinsic);
    if (intrinsic == out->sfm_data.intrinsics.end()) {
      throw FileError(db.source(), "image " + std::to_string(view.id_view) + " refers to missing camera " +
                                       std::to_string(view.id_intrinsic));
    }
    view.width = intrinsic->second.width();
    view.height = intrinsic->second.height();
    out->sfm_data.views[view.id_view] = view;
  }
}

// The image of a per-image row (keypoints, descriptors), which must exist.
IndexT RequireImage(const Connection& db, const ColmapDatabase& out, int64_t image_id, const char* table) {
  const auto id = static_cast<IndexT>(image_id);
  if (out.sfm_data.views.count(id) == 0) {
    throw FileError(db.source(), std::string(table) + " row for missing image " + std::to_string(image_id));
  }
  return id;
}

// Keypoint from a row of 2, 4 or 6 floats (x y [scale orientation | a11 a12 a21 a22]).
Keypoint DecodeKeypoint(const float* row, int64_t cols) {
  Keypoint keypoint;
  keypoint.x = row[0] - static_cast<float>(kColmapPixelOffset);  // exact in float below 2^23
  keypoint.y = row[1] - static_cast<float>(kColmapPixelOffset);
  if (cols == 4) {
    keypoint.scale = row[2];
    keypoint.orientation = row[3];
  } else if (cols == 6) {
    // The affine frame maps the unit circle of the feature into the image: its columns are the
    // rotated, scaled axes, so scale is their mean length and orientation the angle of the first.
    const float a11 = row[2], a12 = row[3], a21 = row[4], a22 = row[5];
    keypoint.scale = 0.5f * (std::hypot(a11, a21) + std::hypot(a12, a22));
    keypoint.orientation = std::atan2(a21, a11);
  }
  return keypoint;
}

void ReadKeypoints(Connection& db, ColmapDatabase* out) {
  Statement rows = db.Prepare("SELECT image_id, rows, cols, data FROM keypoints ORDER BY image_id");
  while (rows.Step()) {
    const IndexT image_id = RequireImage(db, *out, rows.ColumnInt64(0), "keypoints");
    const int64_t num = rows.ColumnInt64(1);
    const int64_t cols = rows.ColumnInt64(2);
    const std::string what = "keypoints of image " + std::to_string(image_id);
    if (num < 0) throw FileError(db.source(), what + ": the row count " + std::to_string(num) + " is negative");
    if (num > 0 && cols != 2 && cols != 4 && cols != 6) {
      throw FileError(db.source(), what + " have " + std::to_string(cols) + " columns, expected 2, 4 or 6");
    }
    const std::vector<float> values =
        DecodeArray<float>(rows.ColumnBlob(3), static_cast<size_t>(num * cols), db.source(), what);
    FeatureSet& features = out->features[image_id];
    features.keypoints.reserve(static_cast<size_t>(num));
    for (int64_t k = 0; k < num; ++k) {
      features.keypoints.push_back(DecodeKeypoint(&values[k * cols], cols));
      const Keypoint& keypoint = features.keypoints.back();
      if (!std::isfinite(keypoint.x) || !std::isfinite(keypoint.y) || !std::isfinite(keypoint.scale) ||
          !std::isfinite(keypoint.orientation)) {
        throw FileError(db.source(), what + ": keypoint " + std::to_string(k) + " is not finite");
      }
    }
  }
}

void ReadDescriptors(Connection& db, ColmapDatabase* out) {
  Statement rows = db.Prepare("SELECT image_id, rows, cols, data FROM descriptors ORDER BY image_id");
  while (rows.Step()) {
    const IndexT image_id = RequireImage(db, *out, rows.ColumnInt64(0), "descriptors");
    const int64_t num = rows.ColumnInt64(1);
    if (num == 0) continue;
    const std::string what = "descriptors of image " + std::to_string(image_id);
    if (rows.ColumnInt64(2) != kDescriptorSize) {
      throw FileError(db.source(), what + " have " + std::to_string(rows.ColumnInt64(2)) +
                                       " columns, expected " + std::to_string(kDescriptorSize));
    }
    FeatureSet& features = out->features[image_id];
    if (num < 0 || static_cast<size_t>(num) != features.size()) {
      throw FileError(db.source(), what + ": " + std::to_string(num) + " rows for " +
                                       std::to_string(features.size()) + " keypoints");
    }
    const std::vector<Descriptor> values =
        DecodeArray<Descriptor>(rows.ColumnBlob(3), static_cast<size_t>(num), db.source(), what);
    features.descriptors = values;
  }
}

// Decodes an N x 2 uint32 match blob and checks the indices against both images' keypoints.
std::vector<FeatureMatch> DecodeMatches(const Connection& db, const ColmapDatabase& out,
                                        const Statement& rows, const ViewPair& pair,
                                        const std::string& what) {
  const int64_t num = rows.ColumnInt64(1);
  if (num < 0) throw FileError(db.source(), what + ": the row count " + std::to_string(num) + " is negative");
  if (rows.ColumnInt64(2) != 2) {
    throw FileError(db.source(),
                    what + " have " + std::to_string(rows.ColumnInt64(2)) + " columns, expected 2");
  }
  const std::vector<uint32_t> values =
      DecodeArray<uint32_t>(rows.ColumnBlob(3), static_cast<size_t>(2 * num), db.source(), what);
  const auto count = [&](IndexT view) {
    const auto found = out.features.find(view);
    return found == out.features.end() ? size_t{0} : found->second.size();
  };
  const size_t size_first = count(pair.first), size_second = count(pair.second);
  std::vector<FeatureMatch> matches(static_cast<size_t>(num));
  for (size_t k = 0; k < matches.size(); ++k) {
    matches[k] = {values[2 * k], values[2 * k + 1]};
    if (matches[k].i >= size_first || matches[k].j >= size_second) {
      throw FileError(db.source(), what + " reference a keypoint that does not exist");
    }
  }
  return matches;
}

ViewPair RequirePair(const Connection& db, const ColmapDatabase& out, int64_t pair_id, const char* table) {
  if (pair_id < 0 || static_cast<uint64_t>(pair_id) / kMaxNumImages >= kMaxNumImages) {
    throw FileError(db.source(), std::string(table) + ": pair_id " + std::to_string(pair_id) +
                                     " is not a pair of image ids (id1 * 2147483647 + id2)");
  }
  const ViewPair pair = ColmapPairFromId(static_cast<uint64_t>(pair_id));
  if (out.sfm_data.views.count(pair.first) == 0 || out.sfm_data.views.count(pair.second) == 0) {
    throw FileError(db.source(), std::string(table) + " row for pair " + std::to_string(pair_id) +
                                     " names a missing image");
  }
  return pair;
}

std::string PairName(const char* what, const ViewPair& pair) {
  return std::string(what) + " of images " + std::to_string(pair.first) + "-" + std::to_string(pair.second);
}

void ReadMatches(Connection& db, ColmapDatabase* out) {
  Statement rows =
      db.Prepare("SELECT pair_id, rows, cols, data FROM matches WHERE rows != 0 ORDER BY pair_id");
  while (rows.Step()) {
    const ViewPair pair = RequirePair(db, *out, rows.ColumnInt64(0), "matches");
    out->putative[pair] = DecodeMatches(db, *out, rows, pair, PairName("matches", pair));
  }
}

std::optional<RelativePose> DecodeRelativePose(const Connection& db, const std::string& qvec_blob,
                                               const std::string& tvec_blob, const std::string& what) {
  if (qvec_blob.empty() || tvec_blob.empty()) return std::nullopt;
  const std::vector<double> q = DecodeArray<double>(qvec_blob, 4, db.source(), what + " qvec");
  const std::vector<double> t = DecodeArray<double>(tvec_blob, 3, db.source(), what + " tvec");
  const Eigen::Quaterniond quaternion(q[0], q[1], q[2], q[3]);
  if (!quaternion.coeffs().allFinite() || !std::isfinite(t[0]) || !std::isfinite(t[1]) || !std::isfinite(t[2])) {
    throw FileError(db.source(), what + ": the relative pose (qvec, tvec) is not finite");
  }
  if (quaternion.norm() == 0.0) return std::nullopt;  // COLMAP 3.8's "not computed"
  // COLMAP's qvec/tvec map camera-1 to camera-2 coordinates, exactly RelativePose's i -> j.
  return RelativePose(quaternion.normalized().toRotationMatrix(), Eigen::Vector3d(t[0], t[1], t[2]));
}

void ReadTwoViewGeometries(Connection& db, ColmapDatabase* out) {
  const bool has_pose =
      db.HasColumn("two_view_geometries", "qvec") && db.HasColumn("two_view_geometries", "tvec");
  Statement rows = db.Prepare(std::string("SELECT pair_id, rows, cols, data, config, F, E, H") +
                              (has_pose ? ", qvec, tvec" : "") +
                              " FROM two_view_geometries WHERE rows != 0 ORDER BY pair_id");
  while (rows.Step()) {
    const ViewPair pair = RequirePair(db, *out, rows.ColumnInt64(0), "two_view_geometries");
    const std::string what = PairName("two-view geometry", pair);
    ColmapTwoViewGeometry geometry;
    geometry.inliers = DecodeMatches(db, *out, rows, pair, what + " inliers");
    geometry.config = static_cast<int>(rows.ColumnInt64(4));
    geometry.F = colmap_blobs::DecodeMatrix3(rows.ColumnBlob(5), db.source(), what + " F");
    geometry.E = colmap_blobs::DecodeMatrix3(rows.ColumnBlob(6), db.source(), what + " E");
    geometry.H = colmap_blobs::DecodeMatrix3(rows.ColumnBlob(7), db.source(), what + " H");
    if (has_pose)
      geometry.relative_pose = DecodeRelativePose(db, rows.ColumnBlob(8), rows.ColumnBlob(9), what);
    out->verified[pair] = std::move(geometry);
  }
}

}  // namespace

uint64_t ColmapPairId(IndexT image_id1, IndexT image_id2) {
  const ViewPair pair = MakeViewPair(image_id1, image_id2);
  return kMaxNumImages * pair.first + pair.second;
}

ViewPair ColmapPairFromId(uint64_t pair_id) {
  return {static_cast<IndexT>(pair_id / kMaxNumImages), static_cast<IndexT>(pair_id % kMaxNumImages)};
}

ColmapDatabase ReadColmapDatabase(const fs::path& path) {
  Connection db = Connection::OpenReadOnly(path.string());
  colmap_sqlite::RequireColmapTables(db);
  ColmapDatabase out;
  ReadCameras(db, &out);
  ReadImages(db, &out);
  ReadKeypoints(db, &out);
  ReadDescriptors(db, &out);
  ReadMatches(db, &out);
  ReadTwoViewGeometries(db, &out);
  return out;
}

}  // namespace sfm_pruning
