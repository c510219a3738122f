#include "sfm_pruning/io/ground_truth_cameras.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/SVD>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

constexpr size_t kFieldsPerCamera = 20;
// The files print rotation entries with about six significant digits, so R R^T differs from I
// by ~1e-6; anything beyond this is not a rotation matrix but a wrong file.
constexpr double kMaxOrthonormalityError = 1e-3;

// Parses one token as a finite double; throws with the line number otherwise.
double ParseNumber(const std::string& token, const std::string& where) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
    throw Error(where + "'" + token + "' is not a number");
  }
  return value;
}

uint32_t ParseImageSize(const std::string& token, const std::string& where) {
  const double value = ParseNumber(token, where);
  if (value < 1 || value > 1e6 || value != std::floor(value)) {
    throw Error(where + "image size '" + token + "' is not a positive integer");
  }
  return static_cast<uint32_t>(value);
}

// Nearest rotation (Frobenius norm) to a matrix that is already almost one.
Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& M) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace

SfmData ReadGroundTruthCameras(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::istringstream text(ReadFileToString(path, /*binary=*/false));
  SfmData data;
  std::set<std::string> names;
  std::string line;
  for (size_t line_number = 1; std::getline(text, line); ++line_number) {
    std::istringstream fields_stream(line);
    std::vector<std::string> fields;
    for (std::string token; fields_stream >> token;) fields.push_back(token);
    if (fields.empty() || fields[0][0] == '#') continue;
    // Every message names the file and the line: "<file>: line 7: ...".
    const std::string where = file + ": line " + std::to_string(line_number) + ": ";
    if (fields.size() != kFieldsPerCamera) {
      throw Error(where + "expected " + std::to_string(kFieldsPerCamera) + " fields (name width height fx fy cx cy skew R t), found " +
                  std::to_string(fields.size()));
    }
    std::vector<double> values(kFieldsPerCamera, 0.0);
    for (size_t i = 3; i < kFieldsPerCamera; ++i) values[i] = ParseNumber(fields[i], where);
    const uint32_t width = ParseImageSize(fields[1], where);
    const uint32_t height = ParseImageSize(fields[2], where);
    const double fx = values[3], fy = values[4], cx = values[5], cy = values[6], skew = values[7];
    if (!(fx > 0.0) || !(fy > 0.0)) throw Error(where + "focal lengths must be positive");
    if (skew != 0.0) throw Error(where + "non-zero skew is not supported by PruneSfM's camera models");

    Eigen::Matrix3d R;
    R << values[8], values[9], values[10], values[11], values[12], values[13], values[14], values[15], values[16];
    const double orthonormality_error = (R * R.transpose() - Eigen::Matrix3d::Identity()).norm();
    if (orthonormality_error > kMaxOrthonormalityError || R.determinant() <= 0.0) {
      throw Error(where + "R is not a rotation matrix");
    }
    const Eigen::Vector3d t(values[17], values[18], values[19]);

    const std::string& name = fields[0];
    if (!names.insert(name).second) throw Error(where + "image '" + name + "' is listed twice");

    const IndexT id = static_cast<IndexT>(data.views.size());
    View view;
    view.id_view = view.id_intrinsic = view.id_pose = id;
    view.filename = name;
    view.width = width;
    view.height = height;
    data.views[id] = view;
    data.intrinsics[id] = fx == fy ? CameraIntrinsics::Pinhole(width, height, fx, cx, cy)
                                   : CameraIntrinsics(CameraModel::kPinholeFxFy, width, height, {fx, fy, cx, cy});
    data.poses[id] = Pose::FromRotationTranslation(NearestRotation(R), t);
  }
  if (data.views.empty()) throw FileError(file, "no camera found (expected gt_cameras.txt lines)");
  return data;
}

void WriteGroundTruthCameras(const SfmData& data, const std::filesystem::path& path) {
  for (const auto& [id, view] : data.views) {
    if (!data.IsPosed(view)) continue;
    const CameraIntrinsics& k = data.IntrinsicsOf(view);
    if (!IsPinholeFamily(k.model()) || k.HasDistortion()) {
      throw FileError(path.string(), "view " + std::to_string(id) + " has a " + CameraModelName(k.model()) +
                                         " camera with distortion; gt_cameras.txt holds undistorted pinholes only");
    }
  }
  WriteFileAtomically(path, /*binary=*/false, [&](std::ostream& out) {
    out << "# image_name width height fx fy cx cy skew r00 r01 r02 r10 r11 r12 r20 r21 r22 tx ty tz\n";
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (const auto& [id, view] : data.views) {
      if (!data.IsPosed(view)) continue;
      const CameraIntrinsics& k = data.IntrinsicsOf(view);
      const Pose& pose = data.PoseOf(view);
      const Eigen::Vector2d pp = k.PrincipalPoint();
      const Eigen::Vector3d t = pose.translation();
      out << view.RelativeImagePath() << ' ' << view.width << ' ' << view.height << ' ' << k.FocalX() << ' '
          << k.FocalY() << ' ' << pp.x() << ' ' << pp.y() << " 0";
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out << ' ' << pose.rotation(r, c);
      }
      out << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << '\n';
    }
  });
}

}  // namespace sfm_pruning
